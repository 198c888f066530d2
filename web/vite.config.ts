// Vite config for the static site. Root is web/, output goes to /dist at the repo root.
// base './' so the build works from any sub-path. Pyodide's runtime files are served by the
// site itself (dev: middleware; build: emitted assets) — nothing is fetched from another origin.
import { createLogger, defineConfig, type Plugin } from 'vite';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { dirname, resolve } from 'node:path';
import { offlineCache } from './offline/plugin';
import { createHash } from 'node:crypto';
import { reportCPython, seedKey } from './build/prerender';
import { writeSchema } from './build/schema';
import { SNAPSHOT_PYODIDE_VERSION, makeSnapshot, pulabFiles } from './build/snapshot';
import { precompress } from './build/compress';
import { embedScript } from './build/embed';
import { SnapshotUnpacker, packSnapshot } from './src/snapshot-pack';

const here = dirname(fileURLToPath(import.meta.url));
// Before anything is bundled: the form is built from pulab's input schema.
writeSchema();
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

const sha = (b: string | Uint8Array): string => createHash('sha256').update(b).digest('hex');

interface SnapshotInfo {
  file: string;
  /** The heap's size (the unpacked snapshot's). */
  size: number;
  /** The packed file's size (web/src/snapshot-pack.ts). */
  bytes: number;
  pyodideVersion: string;
}
/** Made once per build and shared by the page's and the worker's plugin instances. */
let snapshotJob: Promise<{ info: SnapshotInfo; bytes: Uint8Array } | null> | null = null;

function buildSnapshot(warn: (m: string) => void): Promise<{ info: SnapshotInfo; bytes: Uint8Array } | null> {
  snapshotJob ??= (async () => {
    if (process.env.PULAB_SNAPSHOT === '0') return null;
    const key = seedKey();
    const r = await makeSnapshot(pyodideDir + '/', pulabFiles(repo), key, reportCPython(key));
    if (!r.ok) {
      warn(`no Python memory snapshot (${r.reason}); pages boot Python normally`);
      return null;
    }
    // Shipped without its zero pages; unpacked here as the worker will, and checked byte for byte.
    const packed = packSnapshot(r.bytes);
    const back = new SnapshotUnpacker(new Uint8Array(r.bytes.length));
    for (let at = 0; at < packed.length; at += 65536) back.push(packed.subarray(at, at + 65536));
    if (Buffer.compare(back.finish(), r.bytes) !== 0) {
      warn('no Python memory snapshot (the packed snapshot does not unpack to the heap); pages boot Python normally');
      return null;
    }
    return { bytes: packed, info: { file: `snapshot-${sha(packed).slice(0, 12)}.bin`, size: r.bytes.length, bytes: packed.length, pyodideVersion: SNAPSHOT_PYODIDE_VERSION } };
  })();
  return snapshotJob;
}

/**
 * `virtual:pulab-build`: what the build knows that the page and worker need at once — the seed
 * report prerendered by CPython, a hash of the pulab sources (the key of cached reports), and the
 * memory snapshot's file name and size (null: boot normally). The snapshot is made only by
 * `vite build` (PULAB_SNAPSHOT=0 skips it); the dev server boots normally. `emit`: the page's
 * instance writes the snapshot file, the worker's only reads its name.
 */
function pulabBuild(emit: boolean): Plugin {
  const id = 'virtual:pulab-build';
  let build = false;
  return {
    name: 'pulab-build',
    configResolved(c) {
      build = c.command === 'build';
    },
    resolveId: (s) => (s === id ? `\0${id}` : null),
    async load(s) {
      if (s !== `\0${id}`) return null;
      const snap = build ? await buildSnapshot((m) => this.warn(m)) : null;
      const key = seedKey();
      return [
        `export const PULAB_HASH = ${JSON.stringify(sha(JSON.stringify(pulabFiles(repo))).slice(0, 16))};`,
        `export const SEED_KEY = ${JSON.stringify(key)};`,
        `export const SEED_RESULT = ${JSON.stringify(reportCPython(key))};`,
        `export const SNAPSHOT = ${JSON.stringify(snap?.info ?? null)};`,
      ].join('\n');
    },
    async generateBundle() {
      const snap = emit && build ? await buildSnapshot((m) => this.warn(m)) : null;
      if (snap) this.emitFile({ type: 'asset', fileName: `pyodide/${snap.info.file}`, source: snap.bytes });
    },
  };
}

/**
 * index.html asks for the report runtime's worker script from its head, beside the page's own
 * first script (which starts the worker): the worker's request then finds it in the HTTP cache
 * (a hashed name, cached for good) or joins the download, one round trip earlier. Only the small
 * script: Pyodide's files and the snapshot are fetched by the worker (preloaded in the page, every
 * embed frame would hold its own copy).
 */
function preloadWorker(): Plugin {
  return {
    name: 'pulab-preload-worker',
    apply: 'build',
    transformIndexHtml: {
      order: 'post',
      handler(html, ctx) {
        if (!ctx.bundle || !/(^|\/)index\.html$/.test(ctx.filename)) return html;
        const worker = Object.keys(ctx.bundle).find((f) => /^assets\/worker-[\w-]+\.js$/.test(f));
        if (!worker) return html;
        return { html, tags: [{ tag: 'link', attrs: { rel: 'modulepreload', crossorigin: true, href: `./${worker}` }, injectTo: 'head' }] };
      },
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
  plugins: [pyodideAssets(), pulabBuild(true), preloadWorker(), embedScript(resolve(here, 'src/embed/element.ts'), 'es2022'), precompress(resolve(repo, 'node_modules/.cache/pulab-compress')), offlineCache()],
  optimizeDeps: { exclude: ['pyodide'] },
  worker: { format: 'es', plugins: () => [pulabBuild(false)] },
  server: { fs: { allow: [repo] } },
  build: {
    outDir: resolve(repo, 'dist'),
    emptyOutDir: true,
    target: 'es2022',
    chunkSizeWarningLimit: 1500,
    assetsInlineLimit: 0,
    rollupOptions: {
      // embed.js is built apart, as a classic script (build/embed.ts).
      input: { index: resolve(here, 'index.html'), course: resolve(here, 'course.html') },
      output: { entryFileNames: 'assets/[name]-[hash].js' },
    },
  },
});
