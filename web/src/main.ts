// Start Python first (the worker boots Pyodide while the page's own code loads), then the page.
import { startRuntime } from './runtime';

const client = startRuntime('report');

void import('./app').then(({ App }) => {
  const app = new App(document.getElementById('app')!);
  app.session.simWorkerFactory = () => startRuntime('sim');
  app.start(client);
  (window as unknown as { pulab: unknown }).pulab = app;
});
