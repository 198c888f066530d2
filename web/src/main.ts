import { PulabClient } from './rpc';
const w = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module' });
const c = new PulabClient(w as unknown as ConstructorParameters<typeof PulabClient>[0], {
  onReady: (ms) => (document.getElementById('app')!.textContent = `ready ${ms}`),
});
c.init(new URL('pyodide/', document.baseURI).href);
