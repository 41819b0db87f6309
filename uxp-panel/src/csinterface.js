/* D-former panel: the few CSInterface calls the panel uses, written against CEP's native bridge
 * `window.__adobe_cep__` (what Adobe's CSInterface.js wraps). Only host-cep.js uses this.
 *
 *   evalScript(script, callback)      run ExtendScript in Illustrator; callback(resultString)
 *   getHostEnvironment()              { appName, appVersion, appSkinInfo: { panelBackgroundColor: { color: {red,green,blue} } } }
 *   addEventListener(type, handler)   CSXS events, e.g. 'com.adobe.csxs.events.ThemeColorChanged',
 *                                     'documentAfterActivate', 'documentAfterDeactivate',
 *                                     'com.adobe.csxs.events.panelWindowStatusChanged'
 *   getSystemPath('extension')        the extension's folder as a plain path (to reload the bridge)
 *
 * Adobe's full CSInterface.js (≈1,200 lines) is not bundled: these five native calls are all we need,
 * and they exist unchanged from CEP 4 to CEP 12. */
(function (DF) {
  'use strict';
  function CSInterface(native) {
    this.native = native || window.__adobe_cep__;
    if (!this.native) throw new Error('Not running inside Adobe CEP (window.__adobe_cep__ is missing).');
  }
  CSInterface.THEME_COLOR_CHANGED_EVENT = 'com.adobe.csxs.events.ThemeColorChanged';
  CSInterface.prototype.evalScript = function (script, callback) {
    this.native.evalScript(script, callback || function () {});
  };
  /** Promise form of evalScript; the result is ExtendScript's string value ("EvalScript error." on failure). */
  CSInterface.prototype.evalScriptAsync = function (script) {
    var self = this;
    return new Promise(function (resolve) {
      self.native.evalScript(script, resolve);
    });
  };
  /** Like CSInterface.getSystemPath: the native answer is a file: URL; decoded, without the scheme
   * ("file:///C:/…" → "C:/…" on Windows, "file:///Users/…" → "/Users/…" on macOS). */
  CSInterface.prototype.getSystemPath = function (type) {
    if (!this.native.getSystemPath) return '';
    var url = decodeURI(String(this.native.getSystemPath(type) || ''));
    return /^file:\/\/\/[A-Za-z]:/.test(url) ? url.slice(8) : url.replace(/^file:\/\//, '');
  };
  CSInterface.prototype.getHostEnvironment = function () {
    var env = this.native.getHostEnvironment();
    return typeof env === 'string' ? JSON.parse(env) : env;
  };
  CSInterface.prototype.addEventListener = function (type, handler) {
    this.native.addEventListener(type, function (event) {
      var e = event;
      if (typeof e === 'string') {
        try {
          e = JSON.parse(e);
        } catch (notJson) {
          void notJson;
          e = { type: type, data: event };
        }
      }
      handler(e);
    });
  };
  DF.CSInterface = CSInterface;
})(window.DF = window.DF || {});
