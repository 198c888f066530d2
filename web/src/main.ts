// Start Python first (the worker boots Pyodide while the page's own code loads), then the page.
import { startRuntime } from './runtime';

const client = startRuntime('report');

// A stylesheet that fails to load (blocked, offline) must not stop the page's code: Vite's preload
// would reject the import below; without the CSS the form and the numbers still work.
window.addEventListener('vite:preloadError', (ev) => {
  const e = (ev as Event & { payload?: unknown }).payload;
  if (e instanceof Error && /CSS/.test(e.message)) ev.preventDefault();
});

void import('./app').then(({ App }) => {
  const app = new App(document.getElementById('app')!);
  app.session.simWorkerFactory = (generation) => startRuntime('sim', generation);
  app.start(client, (generation) => startRuntime('report', generation));
}).catch((e: unknown) => {
  // The page's own code did not load (offline, blocked, removed by a new deployment): say so in
  // both languages (i18n is in that code) and offer the one thing that helps.
  console.warn('page code failed to load:', e);
  const reload = Object.assign(document.createElement('button'), { type: 'button', textContent: 'Reload / 重新加载', onclick: () => location.reload() });
  const box = Object.assign(document.createElement('div'), { className: 'load-failed', role: 'alert',
    textContent: 'pu-lab could not load its page code (offline or blocked?). · pu-lab 无法加载页面代码（离线或被拦截？）。 ' });
  box.append(reload);
  document.getElementById('app')?.replaceChildren(box);
});
