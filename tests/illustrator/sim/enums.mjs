// Illustrator scripting enumerations used by the D-former scripts, with the numeric values of the
// published typings (types-for-adobe/Illustrator/2022). ExtendScript enumerators print as
// "Enum.NAME" and compare with == to themselves; we model them as frozen objects with valueOf/toString.

function enumeration(name, members) {
  const e = {};
  for (const [key, value] of Object.entries(members)) {
    e[key] = Object.freeze({ valueOf: () => value, toString: () => `${name}.${key}` });
  }
  return Object.freeze(e);
}

export const PointType = enumeration('PointType', { SMOOTH: 1, CORNER: 2 });
export const PathPointSelection = enumeration('PathPointSelection', {
  NOSELECTION: 1, ANCHORPOINT: 2, LEFTDIRECTION: 3, RIGHTDIRECTION: 4, LEFTRIGHTPOINT: 5,
});
export const Transformation = enumeration('Transformation', {
  DOCUMENTORIGIN: 1, TOPLEFT: 2, LEFT: 3, BOTTOMLEFT: 4, TOP: 5, CENTER: 6, BOTTOM: 7,
  TOPRIGHT: 8, RIGHT: 9, BOTTOMRIGHT: 10,
});
export const RulerUnits = enumeration('RulerUnits', {
  Unknown: 1, Inches: 2, Centimeters: 3, Points: 4, Picas: 5, Millimeters: 6, Qs: 7, Pixels: 8,
  // Added in Illustrator 2023 (not in the 2022 typings); the bridge recognises them by name.
  FeetInches: 9, Meters: 10, Yards: 11, Feet: 12,
});
// Application.coordinateSystem (scripting-constants CoordinateSystem) and Document.documentColorSpace.
export const CoordinateSystem = enumeration('CoordinateSystem', { DOCUMENTCOORDINATESYSTEM: 0, ARTBOARDCOORDINATESYSTEM: 1 });
export const DocumentColorSpace = enumeration('DocumentColorSpace', { RGB: 1, CMYK: 2 });
export const Justification = enumeration('Justification', {
  LEFT: 0, RIGHT: 1, CENTER: 2, FULLJUSTIFYLASTLINELEFT: 3, FULLJUSTIFYLASTLINERIGHT: 4,
  FULLJUSTIFYLASTLINECENTER: 5, FULLJUSTIFY: 6,
});

// Stroke and transparency attributes of PathItem / TextFrame (published typings: StrokeCap, StrokeJoin, BlendModes).
export const StrokeCap = enumeration('StrokeCap', { BUTTENDCAP: 1, ROUNDENDCAP: 2, PROJECTINGENDCAP: 3 });
export const StrokeJoin = enumeration('StrokeJoin', { MITERENDJOIN: 1, ROUNDENDJOIN: 2, BEVELENDJOIN: 3 });
export const BlendModes = enumeration('BlendModes', {
  NORMAL: 0, MULTIPLY: 1, SCREEN: 2, OVERLAY: 3, SOFTLIGHT: 4, HARDLIGHT: 5, COLORDODGE: 6, COLORBURN: 7,
  DARKEN: 8, LIGHTEN: 9, DIFFERENCE: 10, EXCLUSION: 11, HUE: 12, SATURATIONBLEND: 13, COLORBLEND: 14, LUMINOSITY: 15,
});

/** Short unit name ↔ RulerUnits member, for setting up simulated documents. */
export const UNIT_MEMBERS = {
  mm: 'Millimeters', cm: 'Centimeters', in: 'Inches', pt: 'Points', px: 'Pixels', pc: 'Picas',
  q: 'Qs', m: 'Meters', ft: 'Feet', yd: 'Yards', unknown: 'Unknown',
};
