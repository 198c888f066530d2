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
  (window as unknown as { pulab: unknown }).pulab = app;
});
