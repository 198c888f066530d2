// Build time: dist/ carries precompressed twins (name.br, name.gz) of every compressible file, so
// a static server sends them as they are (README, "Serving"). A twin is kept only where it is
// smaller than 95 % of the original (python_stdlib.zip is deflated already).
import type { Plugin } from 'vite';
import { readFile, readdir, stat, writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import { promisify } from 'node:util';
import { brotliCompress, constants, gzip } from 'node:zlib';

const br = promisify(brotliCompress);
const gz = promisify(gzip);
export const COMPRESSIBLE = /\.(html|js|mjs|css|json|wasm|bin|svg|txt|map|zip|ttf)$/;
/** Brotli's best level costs ~30 s on the 9.6 MB wasm; level 9 is within 12 % of it in 5 % of the time. */
const quality = (size: number): number => (size > 1 << 20 ? 9 : 11);

async function files(dir: string): Promise<string[]> {
  const out: string[] = [];
  for (const e of await readdir(dir, { withFileTypes: true })) {
    const p = join(dir, e.name);
    if (e.isDirectory()) out.push(...(await files(p)));
    else if (COMPRESSIBLE.test(e.name)) out.push(p);
  }
  return out;
}

export async function compressDir(dir: string): Promise<{ files: number; bytes: number; br: number }> {
  let bytes = 0;
  let brBytes = 0;
  let n = 0;
  for (const f of await files(dir)) {
    const body = await readFile(f);
    if (body.length < 1024) continue;
    const [b, g] = await Promise.all([
      br(body, { params: { [constants.BROTLI_PARAM_QUALITY]: quality(body.length), [constants.BROTLI_PARAM_SIZE_HINT]: body.length } }),
      gz(body, { level: 9 }),
    ]);
    bytes += body.length;
    brBytes += Math.min(body.length, b.length);
    if (b.length < 0.95 * body.length) await writeFile(`${f}.br`, b);
    if (g.length < 0.95 * body.length) await writeFile(`${f}.gz`, g);
    n++;
  }
  return { files: n, bytes, br: brBytes };
}

export function precompress(): Plugin {
  let outDir = '';
  return {
    name: 'pulab-precompress',
    apply: 'build',
    configResolved(c) {
      outDir = c.build.outDir;
    },
    async closeBundle() {
      if ((await stat(outDir).catch(() => null)) === null) return;
      const r = await compressDir(outDir);
      this.info?.(`precompressed ${r.files} files: ${(r.bytes / 2 ** 20).toFixed(1)} MiB → ${(r.br / 2 ** 20).toFixed(1)} MiB brotli`);
    },
  };
}
