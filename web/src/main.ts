// Start Python first (the worker boots Pyodide while the page's own code loads), then the page.
import { PulabClient, type WorkerLike } from './rpc';

const worker = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: 'pulab' });
const client = new PulabClient(worker as unknown as WorkerLike);
client.init(new URL('pyodide/', document.baseURI).href, 60_000);

void import('./app').then(({ App }) => {
  const app = new App(document.getElementById('app')!);
  app.start(client);
  (window as unknown as { pulab: unknown }).pulab = app;
});
