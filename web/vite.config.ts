// Vite config for the static site. Root is web/, output goes to /dist at the repo root.
// base './' so the build works from any sub-path. Pyodide's runtime files are served by the
// site itself (dev: middleware; build: emitted assets) — nothing is fetched from another origin.
import { createLogger, defineConfig, type Plugin } from 'vite';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { dirname, resolve } from 'node:path';
import { offlineCache } from './offline/plugin';

const here = dirname(fileURLToPath(import.meta.url));
const repo = resolve(here, '..');
const pyodideDir = resolve(repo, 'node_modules/pyodide');
/** The runtime files loadPyodide fetches relative to indexURL. */
export const PYODIDE_FILES = ['pyodide.asm.mjs', 'pyodide.asm.wasm', 'python_stdlib.zip', 'pyodide-lock.json'];

const MIME: Record<string, string> = {
  mjs: 'text/javascript', wasm: 'application/wasm', zip: 'application/zip', json: 'application/json',
};

function pyodideAssets(): Plugin {
  return {
    name: 'pulab-pyodide-assets',
    configureServer(server) {
      server.middlewares.use((req, res, next) => {
        const m = /\/pyodide\/([^/?#]+)(?:[?#].*)?$/.exec(req.url ?? '');
        if (!m || !PYODIDE_FILES.includes(m[1])) return next();
        res.setHeader('Content-Type', MIME[m[1].split('.').pop() ?? ''] ?? 'application/octet-stream');
        res.end(readFileSync(resolve(pyodideDir, m[1])));
      });
    },
    generateBundle() {
      for (const f of PYODIDE_FILES) {
        this.emitFile({ type: 'asset', fileName: `pyodide/${f}`, source: readFileSync(resolve(pyodideDir, f)) });
      }
    },
  };
}

// pyodide.mjs imports node:* modules on its Node code path only; in the browser bundle they are
// externalized on purpose. Silence exactly that notice, keep every other warning.
const logger = createLogger();
const quiet = (msg: string): boolean => /node:\w+.*externalized for browser compatibility.*pyodide/s.test(msg);
const warn = logger.warn.bind(logger);
const warnOnce = logger.warnOnce.bind(logger);
const info = logger.info.bind(logger);
logger.warn = (msg, opts) => (quiet(msg) ? undefined : warn(msg, opts));
logger.warnOnce = (msg, opts) => (quiet(msg) ? undefined : warnOnce(msg, opts));
logger.info = (msg, opts) => (quiet(msg) ? undefined : info(msg, opts));

export default defineConfig({
  customLogger: logger,
  root: here,
  base: './',
  publicDir: false,
  plugins: [pyodideAssets(), offlineCache()],
  optimizeDeps: { exclude: ['pyodide'] },
  worker: { format: 'es' },
  server: { fs: { allow: [repo] } },
  build: {
    outDir: resolve(repo, 'dist'),
    emptyOutDir: true,
    target: 'es2022',
    chunkSizeWarningLimit: 1500,
    assetsInlineLimit: 0,
  },
});
