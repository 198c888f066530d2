import { App } from './app';
import type { WorkerLike } from './rpc';

const app = new App(document.getElementById('app')!);
const worker = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: 'pulab' });
app.start(worker as unknown as WorkerLike);
(window as unknown as { pulab: App }).pulab = app;
