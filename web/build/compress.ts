// Build time: dist/ carries precompressed twins (name.zst, name.br, name.gz) of every compressible
// file, so a static server sends them as they are (docs/deploy.md). A twin is kept only where it is
// smaller than 95 % of the original (python_stdlib.zip is deflated already).
import type { Plugin } from 'vite';
import { mkdir, readFile, readdir, rename, rm, stat, writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import { createHash } from 'node:crypto';
import { promisify } from 'node:util';
import { execFile, execFileSync } from 'node:child_process';
import { brotliCompress, constants, gzip } from 'node:zlib';

const br = promisify(brotliCompress);
const gz = promisify(gzip);
export const COMPRESSIBLE = /\.(html|js|mjs|css|json|wasm|bin|svg|txt|map|zip|ttf)$/;
/**
 * Brotli's best level costs ~30 s on the 9.6 MB wasm; level 9 is within 12 % of it in 5 % of the
 * time. The 30 MB snapshot differs in every build (so the cache below cannot help): level 5,
 * 6 % larger than level 9 in a quarter of the time.
 */
const quality = (size: number): number => (size > 16 << 20 ? 5 : size > 1 << 20 ? 9 : 11);
const gzipLevel = (size: number): number => (size > 16 << 20 ? 6 : 9);

/**
 * zstd decodes in half brotli's time (the 17 MB snapshot: 40 against 75 ms here), and the browser
 * decodes the snapshot and the wasm on the boot's critical path: measured side by side, a cold
 * share link went live 50–130 ms sooner. Node 20's zlib has no zstd, so the CLI makes the twins;
 * without it the build ships .br and .gz only. Browsers refuse frames whose window exceeds 8 MB
 * (RFC 9659): wlog=23 holds every level to that. Level 19 is 13 % smaller than brotli's level 9 on
 * the wasm; the snapshot, new in every build, gets 17 (6 s here, against 9 s for 19).
 */
const ZSTD = (() => {
  try {
    execFileSync('zstd', ['--version'], { stdio: 'ignore' });
    return true;
  } catch {
    return false;
  }
})();
const zstdLevel = (size: number): number => (size > 16 << 20 ? 17 : 19);
const run = (args: string[]): Promise<Buffer> => new Promise((resolve, reject) => {
  execFile('zstd', args, { encoding: 'buffer', maxBuffer: 1 << 30 }, (err, out) => (err ? reject(err) : resolve(out)));
});
/** `file` compressed by zstd's CLI, checked by decompressing it (a twin that differs would be served as the file). */
async function zstdFile(file: string, body: Buffer): Promise<Buffer> {
  const out = await run([`-${zstdLevel(body.length)}`, '--zstd=wlog=23', '-q', '-c', file]);
  const tmp = `${file}.${process.pid}.zst-check`;
  await writeFile(tmp, out);
  const back = await run(['-d', '-q', '-c', tmp]).finally(() => rm(tmp, { force: true }));
  if (!back.equals(body)) throw new Error(`zstd twin of ${file} does not decompress to it`);
  return out;
}

async function files(dir: string): Promise<string[]> {
  const out: string[] = [];
  for (const e of await readdir(dir, { withFileTypes: true })) {
    const p = join(dir, e.name);
    if (e.isDirectory()) out.push(...(await files(p)));
    else if (COMPRESSIBLE.test(e.name)) out.push(p);
  }
  return out;
}

/**
 * Compressed bytes are kept by content hash in `cacheDir`: Pyodide's 13 MB never change, so a
 * build compresses only what did (the snapshot, the bundles).
 */
async function cached(cacheDir: string | null, body: Buffer, kind: 'br' | 'gz' | 'zst', make: () => Promise<Buffer>): Promise<Buffer> {
  if (!cacheDir) return make();
  const file = join(cacheDir, `${createHash('sha256').update(body).digest('hex')}.${kind}`);
  const hit = await readFile(file).catch(() => null);
  if (hit) return hit;
  const out = await make();
  await mkdir(cacheDir, { recursive: true });
  const tmp = `${file}.${process.pid}.tmp`;
  await writeFile(tmp, out);
  await rename(tmp, file);
  return out;
}

export async function compressDir(dir: string, cacheDir: string | null = null): Promise<{ files: number; bytes: number; br: number }> {
  let bytes = 0;
  let brBytes = 0;
  let n = 0;
  for (const f of await files(dir)) {
    const body = await readFile(f);
    if (body.length < 1024) continue;
    const [b, g, z] = await Promise.all([
      cached(cacheDir, body, 'br', () => br(body, { params: { [constants.BROTLI_PARAM_QUALITY]: quality(body.length), [constants.BROTLI_PARAM_SIZE_HINT]: body.length } })),
      cached(cacheDir, body, 'gz', () => gz(body, { level: gzipLevel(body.length) })),
      ZSTD ? cached(cacheDir, body, 'zst', () => zstdFile(f, body)) : null,
    ]);
    bytes += body.length;
    brBytes += Math.min(body.length, b.length);
    if (b.length < 0.95 * body.length) await writeFile(`${f}.br`, b);
    if (g.length < 0.95 * body.length) await writeFile(`${f}.gz`, g);
    if (z && z.length < 0.95 * body.length) await writeFile(`${f}.zst`, z);
    n++;
  }
  return { files: n, bytes, br: brBytes };
}

export function precompress(cacheDir: string | null = null): Plugin {
  let outDir = '';
  return {
    name: 'pulab-precompress',
    apply: 'build',
    configResolved(c) {
      outDir = c.build.outDir;
    },
    async closeBundle() {
      if ((await stat(outDir).catch(() => null)) === null) return;
      const r = await compressDir(outDir, cacheDir);
      this.info?.(`precompressed ${r.files} files: ${(r.bytes / 2 ** 20).toFixed(1)} MiB → ${(r.br / 2 ** 20).toFixed(1)} MiB brotli${ZSTD ? '' : '; no zstd CLI: no .zst twins'}`);
      if (!ZSTD) console.warn('pulab build: zstd not found (apt-get install zstd): dist/ has no .zst twins; browsers get brotli');
    },
  };
}
