/* D-former browser app: bundled sample shapes (SVG text, so the page also works from file://).
 * Each set is two different outlines, as students pair them: the perimeters differ on purpose, so
 * Normalize has work to do. Sizes in mm. */
(function (DF) {
  'use strict';
  function svg(w, h, body) {
    return '<svg xmlns="http://www.w3.org/2000/svg" width="' + w + 'mm" height="' + h + 'mm" viewBox="0 0 ' + w + ' ' + h + '">' + body + '</svg>';
  }
  DF.samples = [
    {
      id: 'ellipse-circle',
      name: 'Ellipse + circle',
      files: [
        { name: 'ellipse.svg', text: svg(160, 90, '<ellipse id="ellipse" cx="80" cy="45" rx="70" ry="35"/>') },
        { name: 'circle.svg', text: svg(120, 120, '<circle id="circle" cx="60" cy="60" r="52"/>') },
      ],
    },
    {
      id: 'pebble-circle',
      name: 'Pebble + circle',
      files: [
        {
          name: 'pebble.svg',
          text: svg(170, 120,
            '<path id="pebble" d="M 20 62 C 18 30 52 12 88 16 C 122 20 152 30 150 62 C 148 92 126 106 96 100 C 76 96 62 108 44 104 C 26 100 21 82 20 62 Z"/>'),
        },
        { name: 'circle.svg', text: svg(120, 120, '<circle id="circle" cx="60" cy="60" r="50"/>') },
      ],
    },
    {
      id: 'two-ellipses',
      name: 'Two ellipses (crossed)',
      files: [
        { name: 'ellipse-wide.svg', text: svg(170, 100, '<ellipse id="wide" cx="85" cy="50" rx="76" ry="38"/>') },
        // Drawn upright, so its first anchor is at the end of its minor axis: the wide ellipse's
        // major-axis end meets it, the classic crossed D-form.
        { name: 'ellipse-tall.svg', text: svg(100, 170, '<ellipse id="tall" cx="50" cy="85" rx="40" ry="72"/>') },
      ],
    },
  ];
})(window.DF = window.DF || {});
