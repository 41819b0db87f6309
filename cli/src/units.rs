//! Lengths and the document's scale: what one user unit (viewBox unit) measures on paper.
//!
//! CSS absolute units at 96 px per inch (SVG 1.1 §7.10): 1in = 96px, 1mm = 96/25.4px,
//! 1cm = 96/2.54px, 1pt = 4/3px, 1pc = 16px. With `width="210mm" height="297mm"
//! viewBox="0 0 210 297"` one user unit is 1 mm; without a viewBox one user unit is 1 px
//! (`crate::viewport` works out the scale).

use svgtypes::{Length, LengthUnit};

/// The units a user may name, with their size in CSS px.
pub const UNITS: &[(&str, f64)] = &[
    ("mm", 96.0 / 25.4),
    ("cm", 96.0 / 2.54),
    ("in", 96.0),
    ("pt", 96.0 / 72.0),
    ("pc", 16.0),
    ("px", 1.0),
];

/// Size of a named unit in CSS px, or `None` for an unknown name.
pub fn px_per(unit: &str) -> Option<f64> {
    UNITS
        .iter()
        .find(|(name, _)| *name == unit)
        .map(|(_, px)| *px)
}

fn unit_name(unit: LengthUnit) -> Option<&'static str> {
    Some(match unit {
        LengthUnit::None | LengthUnit::Px => "px",
        LengthUnit::Mm => "mm",
        LengthUnit::Cm => "cm",
        LengthUnit::In => "in",
        LengthUnit::Pt => "pt",
        LengthUnit::Pc => "pc",
        _ => return None,
    })
}

/// A length attribute in CSS px (absolute units only; `%`, `em`, `ex` → `None`).
pub fn length_px(text: &str) -> Option<f64> {
    let len: Length = text.trim().parse().ok()?;
    Some(len.number * px_per(unit_name(len.unit)?)?)
}

/// The document's scale and the unit lengths are shown and entered in.
#[derive(Debug, Clone, PartialEq)]
pub struct Scale {
    /// CSS px per user unit (`crate::viewport::page_px_per_user`).
    pub px_per_user: f64,
    /// Unit for messages and bare numbers in options (`mm`, `px`, …).
    pub unit: String,
}

impl Scale {
    /// From the page's scale (CSS px per user unit) and the display unit: `unit` if given,
    /// else Inkscape's `inkscape:document-units`, else the unit of the root's `width`, else px.
    pub fn new(
        px_per_user: f64,
        width: Option<&str>,
        doc_units: Option<&str>,
        unit: Option<&str>,
    ) -> Result<Scale, String> {
        let width_unit = width
            .and_then(|w| w.trim().parse::<Length>().ok())
            .and_then(|l| unit_name(l.unit))
            .map(str::to_string);
        let unit = unit
            .map(str::to_string)
            .or(doc_units.map(str::to_string))
            .or(width_unit)
            .unwrap_or_else(|| "px".into());
        if px_per(&unit).is_none() {
            return Err(format!(
                "unknown unit `{unit}`; use one of {}",
                UNITS.iter().map(|(n, _)| *n).collect::<Vec<_>>().join(", ")
            ));
        }
        Ok(Scale { px_per_user, unit })
    }

    /// User units → the display unit.
    pub fn to_unit(&self, user: f64) -> f64 {
        user * self.px_per_user / px_per(&self.unit).unwrap_or(1.0)
    }

    /// A length given by the user (`3mm`, `0.1in`, or a bare number in the display unit) → the
    /// display unit (what the core works in, so that its messages speak the user's unit).
    pub fn parse(&self, text: &str) -> Result<f64, String> {
        let len: Length = text
            .trim()
            .parse()
            .map_err(|_| format!("`{text}` is not a length (e.g. 3, 3mm, 0.1in)"))?;
        let unit = match len.unit {
            LengthUnit::None => return Ok(len.number),
            other => unit_name(other).ok_or_else(|| {
                format!("`{text}`: use an absolute unit (mm, cm, in, pt, pc, px)")
            })?,
        };
        if unit == self.unit {
            return Ok(len.number);
        }
        Ok(len.number * px_per(unit).unwrap_or(1.0) / px_per(&self.unit).unwrap_or(1.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_mm_document_has_mm_user_units() {
        let s = Scale::new(96.0 / 25.4, Some("210mm"), None, None).unwrap();
        assert_eq!(s.unit, "mm");
        assert!(
            (s.to_unit(10.0) - 10.0).abs() < 1e-12,
            "wanted 10 mm, got {}",
            s.to_unit(10.0)
        );
        assert!(
            (s.parse("1in").unwrap() - 25.4).abs() < 1e-12,
            "wanted 25.4 mm per inch"
        );
        assert_eq!(
            s.parse("3").unwrap(),
            3.0,
            "bare numbers are in the display unit"
        );
        assert_eq!(
            s.parse("-1mm").unwrap(),
            -1.0,
            "the display unit is not converted"
        );
    }

    #[test]
    fn a_document_without_viewbox_has_px_user_units() {
        let s = Scale::new(1.0, Some("800"), None, Some("mm")).unwrap();
        assert!(
            (s.to_unit(96.0) - 25.4).abs() < 1e-12,
            "wanted 96 px = 25.4 mm, got {}",
            s.to_unit(96.0)
        );
        assert_eq!(
            s.parse("25.4").unwrap(),
            25.4,
            "lengths are read in the display unit"
        );
        assert!(
            (s.parse("96px").unwrap() - 25.4).abs() < 1e-12,
            "96 px = 25.4 mm"
        );
    }

    #[test]
    fn inkscape_display_units_win_over_width_units_and_bad_units_are_named() {
        let s = Scale::new(96.0 / 25.4, Some("100mm"), Some("cm"), None).unwrap();
        assert_eq!(s.unit, "cm");
        assert!((s.to_unit(10.0) - 1.0).abs() < 1e-12);
        let e = Scale::new(1.0, None, None, Some("furlong")).unwrap_err();
        assert!(e.contains("furlong") && e.contains("mm"), "got {e}");
        assert!(s.parse("5%").unwrap_err().contains("absolute unit"));
    }
}
