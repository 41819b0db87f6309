/* D-former panel: host command names in messages. Every message says what to do in plain words
 * ("close the path"); the one table messages/commands.json (shared with the CLI and the Inkscape
 * extension; build.mjs writes it into wasm/commands-table.js) gives each plain phrase in each
 * host's own words. Each host module picks its column (host-cep.js: Illustrator's menus,
 * host-browser.js: plain words); UI code only calls host.advise(text). */
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
  DF.commands = { render: render, hosts: TABLE.hosts.slice() };
})(window.DF = window.DF || {});
