/* D-former panel: the core's messages in the user's units. The core measures in points and prints
 * raw numbers ("Holes of diameter 5.669291338582678 …"); the panel shows lengths in the document's
 * ruler unit ("2.00 mm"), angles rounded, and the option names as the panel labels them.
 * Templates: {L} a length in points, {A} an angle in degrees, {N} a number kept as printed. */
(function (DF) {
  'use strict';
  var NUM = '(-?\\d+(?:\\.\\d+)?(?:e[-+]?\\d+)?)';
  var LABELS = { inset: 'Inset', diameter: 'Hole ⌀', length: 'Length', pitch: 'Pitch', kerf: 'Kerf', target: 'The target perimeter' };
  // [core template, panel template]; the panel template uses the numbers in the same order.
  var RULES = [
    ['Holes of diameter {L} do not fit between connectors {L} apart', 'Holes of {L} ⌀ do not fit between connectors {L} apart'],
    [' (the gaps between teeth reach {L} in)', ' (the gaps between the teeth reach {L} into the piece)'],
    ['An inset of {L} puts holes of diameter {L} across the edge', 'An inset of {L} puts holes of {L} ⌀ across the edge'],
    ['Teeth of length {L} with {A}° flanks do not fit a pitch of {L}', 'Teeth {L} long with {A}° flanks do not fit a pitch of {L}'],
    ['A kerf of {L} makes the leaves ({L} wide) as wide as the pitch {L}', 'A kerf of {L} makes the leaves ({L} wide) as wide as the pitch of {L}'],
    ['Option `kerf`: {L} is not smaller than the hole diameter {L}: the holes would vanish', 'A kerf of {L} is not smaller than the holes ({L} ⌀): the holes would vanish. Use a smaller kerf.'],
    ['Option `pitch`: {L} on a perimeter of {L} gives {N} connectors; at most {N} are allowed', 'A pitch of {L} on a perimeter of {L} gives {N} connectors; at most {N} are allowed: use a larger pitch.'],
    ['different perimeters ({L} and {L};', 'different perimeters ({L} and {L};'],
    ['A seam allowance of {L} makes the cut line', 'A seam allowance of {L} makes the cut line'],
    ['Locking leaves {L} long leave no neck under their head ({L} wide) at a pitch of {L}: make them longer than {L}', 'Locking leaves {L} long leave no neck under their head ({L} wide) at a pitch of {L}: make them longer than {L}'],
    ['A kerf of {L} is as wide as the slots for the locking leaves ({L} across)', 'A kerf of {L} is as wide as the slots for the locking leaves ({L} across)'],
    ['Option `allowance`: must be zero or a positive distance from the seam line to the cut line, got {L}', 'The allowance must be 0 or more (it is {L})'],
  ];
  function compile(template) {
    var parts = template.split(/\{([LAN])\}/);
    var re = '';
    var kinds = [];
    for (var i = 0; i < parts.length; i++) {
      if (i % 2) {
        re += NUM;
        kinds.push(parts[i]);
      } else {
        re += parts[i].replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
      }
    }
    return { re: new RegExp(re, 'g'), kinds: kinds };
  }
  var COMPILED = RULES.map(function (r) { return { from: compile(r[0]), to: r[1] }; });

  /** `message` with its lengths shown by `format(points)` (e.g. "2.00 mm"). */
  function humanize(message, format) {
    var text = String(message);
    COMPILED.forEach(function (rule) {
      text = text.replace(rule.from.re, function () {
        var values = Array.prototype.slice.call(arguments, 1, 1 + rule.from.kinds.length);
        var k = 0;
        return rule.to.replace(/\{([LAN])\}/g, function (m, kind) {
          var v = Number(values[k++]);
          if (kind === 'L') return format(v);
          if (kind === 'A') return String(Math.round(v * 10) / 10);
          return String(v);
        });
      });
    });
    // "Option `inset`: must be a positive number, got -14.17…" → "Inset must be more than 0 (it is −5.00 mm)."
    text = text.replace(new RegExp('Option `(\\w+)`: must be a positive(?:, finite perimeter| number), got ' + NUM), function (m, name, v) {
      return (LABELS[name] || name) + ' must be more than 0 (it is ' + format(Number(v)) + ').';
    });
    // The core calls the pieces "first"/"second"; the panel shows them as A and B.
    var KEY = { first: 'A', second: 'B' };
    // A path measured alone is "the first path" to the core; prefixed with its name it is "the path".
    text = text.replace(/(”: )The first path /g, '$1The path ');
    text = text.replace(/\b(On t|t|T)he (first|second) (piece|path)\b/g, function (m, the, which, what) {
      if (what === 'piece') return (the === 'T' ? 'Piece ' : the === 'On t' ? 'On piece ' : 'piece ') + KEY[which];
      return (the === 'On t' ? 'On the' : the === 'T' ? 'The' : 'the') + ' path of piece ' + KEY[which];
    });
    // One connector is singular ("the holes of connector 3 cross the edge", "gives 1 connector").
    text = text.replace(/\bconnectors (\d+)(?= (?:cross|lie|run|overlap)\b)/g, 'connector $1');
    text = text.replace(/\b1 connectors\b/g, '1 connector');
    return text;
  }
  DF.messages = { humanize: humanize };
})(window.DF = window.DF || {});
