// The Web Worker: thin glue between postMessage, Pyodide and worker-logic.ts.
import { loadPyodide } from 'pyodide';
import { createWorkerLogic, describeError, type PyodideLike } from './worker-logic';
import { PULAB_FILES } from './pysources';
import type { MainToWorker, WorkerToMain } from './protocol';

const scope = self as unknown as {
  postMessage(m: WorkerToMain): void;
  onmessage: ((ev: MessageEvent<MainToWorker>) => void) | null;
};

const logic = createWorkerLogic(
  (m) => scope.postMessage(m),
  async (indexURL) => (await loadPyodide({ indexURL, packages: [] })) as unknown as PyodideLike,
  PULAB_FILES,
);
scope.onmessage = (ev) => logic.onMessage(ev.data);
// A rejection nobody awaited (Pyodide fetches some files on the side) ends the boot with a
// message naming it, instead of an "Uncaught (in promise)" on the page.
self.addEventListener('unhandledrejection', (ev) => {
  ev.preventDefault();
  scope.postMessage({ type: 'fatal', message: describeError(ev.reason) });
});
