// Made by the `pulab-build` plugin in web/vite.config.ts at build (and dev) time.
declare module 'virtual:pulab-build' {
  /** A hash of py/pulab's sources: reports cached by another pulab are not reused. */
  export const PULAB_HASH: string;
  /** The JSON text the page sends for the seed input, and CPython's pulab.api.call_json("report", …) of it. */
  export const SEED_KEY: string;
  export const SEED_RESULT: string;
  /** The Python memory snapshot under pyodide/, or null (boot normally). */
  export const SNAPSHOT: { file: string; size: number; bytes: number; pyodideVersion: string } | null;
}
