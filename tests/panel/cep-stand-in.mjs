// A CEP stand-in for the panel tests: defines `window.__adobe_cep__` (the native object Adobe's
// CSInterface wraps) before the page loads. evalScript goes to the exposed __dformerEvalScript,
// which runs the real illustrator-scripts/*.jsx in the simulated Illustrator DOM (jsx-host.mjs).
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { createHost } from '../illustrator/jsx-host.mjs';

/** The built extension folder (node uxp-panel/build.mjs): getSystemPath('extension'), where the panel reloads the bridge from. */
const EXTENSION = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', 'dist', 'com.dformer.panel');

/** Illustrator's panel brightness presets (appSkinInfo.panelBackgroundColor). */
export const SKINS = { dark: [50, 50, 50], mediumDark: [83, 83, 83], mediumLight: [184, 184, 184], light: [240, 240, 240] };

function installCep({ skin, extensionUrl }) {
  const listeners = {};
  window.__cepSkin = skin;
  window.__cepListeners = listeners;
  window.__adobe_cep__ = {
    evalScript(script, callback) {
      window.__dformerEvalScript(script).then((r) => callback && callback(r));
    },
    getHostEnvironment() {
      const [red, green, blue] = window.__cepSkin;
      return JSON.stringify({
        appName: 'ILST',
        appVersion: '22.0.0',
        appSkinInfo: { panelBackgroundColor: { antialiasLevel: 0, type: 1, color: { red, green, blue, alpha: 255 } } },
      });
    },
    addEventListener(type, fn) {
      (listeners[type] = listeners[type] || []).push(fn);
    },
    getSystemPath(type) {
      return type === 'extension' ? extensionUrl : '';
    },
  };
  /** Test hook: Illustrator changes its brightness and fires ThemeColorChanged. */
  window.__setSkin = (rgb) => {
    window.__cepSkin = rgb;
    for (const fn of listeners['com.adobe.csxs.events.ThemeColorChanged'] || []) fn(JSON.stringify({ type: 'com.adobe.csxs.events.ThemeColorChanged', data: '' }));
  };
}

/** Opens the panel page on `url` with a simulated Illustrator document (in `context` if given, to share
 * localStorage between panel sessions); returns { page, host, calls, errors }. */
export async function openPanel(browser, url, hostOptions, { skin = SKINS.dark, viewport = { width: 300, height: 640 }, context = null } = {}) {
  const host = createHost(hostOptions);
  const page = context ? await context.newPage() : await browser.newPage({ viewport });
  if (context) await page.setViewportSize(viewport);
  const calls = [];
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.exposeFunction('__dformerEvalScript', (script) => {
    calls.push(String(script).slice(0, 40));
    return host.evalScript(script);
  });
  await page.addInitScript(installCep, { skin, extensionUrl: `file://${encodeURI(EXTENSION)}` });
  await page.goto(url);
  return { page, host, calls, errors };
}
