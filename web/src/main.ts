// Start Python first (the worker boots Pyodide while the page's own code loads), then the page.
import { PulabClient, type WorkerLike } from './rpc';

function startWorker(name: string): PulabClient {
  const worker = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name });
  const c = new PulabClient(worker as unknown as WorkerLike);
  c.init(new URL('pyodide/', document.baseURI).href, 60_000);
  return c;
}
const client = startWorker('pulab');

void import('./app').then(({ App }) => {
  const app = new App(document.getElementById('app')!);
  app.session.simWorkerFactory = () => startWorker('pulab-sim');
  app.start(client);
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
