// Emits dist/sw.js (the offline cache, issue 14) from web/offline/sw.js with the list of every
// file of the build and a version that changes whenever any file changes.
import { createHash } from 'node:crypto';
import { readFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Plugin } from 'vite';

const TEMPLATE = resolve(dirname(fileURLToPath(import.meta.url)), 'sw.js');

export function offlineCache(): Plugin {
  return {
    name: 'pulab-offline-cache',
    apply: 'build',
    enforce: 'post',
    generateBundle(_options, bundle) {
      // Precompressed twins (.zst/.br/.gz) are the server's business: the browser asks for the plain name.
      // KaTeX's .woff/.ttf fonts are fallbacks for browsers without woff2 (none that run Pyodide).
      const files = Object.keys(bundle).filter((f) => !/\.(map|br|gz|zst)$/.test(f) && !/KaTeX_.*\.(woff|ttf)$/.test(f)).sort();
      const hash = createHash('sha256');
      for (const f of files) {
        const item = bundle[f];
        hash.update(f).update(item.type === 'chunk' ? item.code : item.source);
      }
      const version = hash.digest('hex').slice(0, 16);
      const source = readFileSync(TEMPLATE, 'utf8')
        .replace("'__PULAB_VERSION__'", JSON.stringify(version))
        .replace('__PULAB_FILES__', JSON.stringify(files));
      this.emitFile({ type: 'asset', fileName: 'sw.js', source });
    },
  };
}
