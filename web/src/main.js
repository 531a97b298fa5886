// Boot: a static snapshot when the page carries its scene (`sphereset view --html`), else the
// live page of the local server, whose token is in the page's own URL.
import { ServerApi } from './api.js';
import { App } from './app.js';
import { wireControls } from './controls.js';
import { installHooks } from './hooks.js';
import { showMessage } from './panels.js';

function source() {
  const data = document.getElementById('sphereset-data');
  if (data) return { api: null, staticScene: JSON.parse(data.textContent) };
  const token = new URLSearchParams(location.search).get('token');
  if (!token) throw new Error('this page needs its token: open the address `sphereset view` printed');
  // The token leaves the address bar and the history once read: it is kept in the page only.
  history.replaceState(null, '', location.pathname);
  return { api: new ServerApi(token), staticScene: null };
}

async function boot(app) {
  const container = document.getElementById('viewport');
  await app.start(container);
  wireControls(app, container);
}

function reportUnexpected() {
  window.addEventListener('error', (e) => showMessage(`error: ${e.message}`, 'error'));
  window.addEventListener('unhandledrejection', (e) => {
    showMessage(`error: ${(e.reason && e.reason.message) || e.reason}`, 'error');
  });
}

reportUnexpected();
let app = null;
let ready;
try {
  app = new App(source());
  ready = boot(app);
} catch (e) {
  ready = Promise.reject(e);
}
ready = ready.catch((e) => {
  showMessage(`the scene could not be shown: ${e.message || e}`, 'error');
  document.getElementById('status').textContent = 'no scene';
  throw e;
});
ready.catch(() => {});  // the failure is on the message line; tests see it through ready
installHooks(app, ready);
