// The Web Worker: thin glue between postMessage, Pyodide and worker-logic.ts.
import { loadPyodide } from 'pyodide';
import { createWorkerLogic, type PyodideLike } from './worker-logic';
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
