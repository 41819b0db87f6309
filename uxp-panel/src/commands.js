/* D-former panel: host command names in messages. Every message says what to do in plain words
 * ("close the path"); the one table messages/commands.json (shared with the CLI and the Inkscape
 * extension; build.mjs writes it into wasm/commands-table.js) gives each plain phrase in each
 * host's own words, and says why a drawn element is skipped (the CLI's words too). Each host module
 * picks its column (host-cep.js: Illustrator's menus, host-browser.js: plain words); UI code only
 * calls host.advise(text). */
(function (DF) {
  'use strict';
  var TABLE = (typeof self !== 'undefined' && self.DFORMER_COMMANDS) || { hosts: ['plain'], advice: [] };

  /** `text` with each plain phrase of the table in `host`'s words ('plain' changes nothing). */
  function render(text, host) {
    var out = String(text);
    TABLE.advice.forEach(function (row) {
      var own = row[host];
      if (own && own !== row.plain) out = out.split(row.plain).join(own);
    });
    return out;
  }
  /** Why a drawn element of this kind ('open', or its tag: 'text', 'image', …) is not offered as a piece. */
  function skipped(kind) {
    return (TABLE.skipped && TABLE.skipped[kind]) || (kind === 'open' ? 'an open path' : 'not an outline');
  }
  DF.commands = { render: render, skipped: skipped, hosts: TABLE.hosts.slice() };
})(window.DF = window.DF || {});
