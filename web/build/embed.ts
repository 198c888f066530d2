// Build time: dist/embed.js, the docs pages' one script tag, as a single classic script (an IIFE:
// no import/export, no import.meta). The same file then runs from `<script src>` — which another
// origin's page may load with no CORS header on the pu-lab server — and from
// `<script type="module" src>`. It is a build of its own (the site's bundles are ES modules) whose
// output is added to the site's bundle as an asset, at a name that never changes (not hashed, so
// servers must revalidate it: docs/deploy.md); the offline cache and the precompressed twins
// include it like any other file.
import { build, type Plugin } from 'vite';

/** embed.js's code: `entry` bundled alone into one IIFE for `target`; throws if it is not a classic script. */
export async function buildEmbed(entry: string, target: string): Promise<string> {
  const out = await build({
    configFile: false,
    logLevel: 'warn',
    publicDir: false,
    build: {
      write: false,
      emptyOutDir: false,
      target,
      minify: true,
      lib: { entry, formats: ['iife'], name: 'puLabEmbed', fileName: () => 'embed.js' },
    },
  });
  const chunks = (Array.isArray(out) ? out : [out]).flatMap((o) => ('output' in o ? o.output : []));
  const js = chunks.find((c) => c.type === 'chunk' && c.isEntry);
  if (!js || js.type !== 'chunk' || chunks.length !== 1) throw new Error(`embed.js: expected one chunk, got ${chunks.map((c) => c.fileName).join(', ')}`);
  if (/\bimport\.meta\b|^\s*(import|export)\b/m.test(js.code)) throw new Error('embed.js is not a classic script (import/export or import.meta left in it)');
  return js.code;
}

export function embedScript(entry: string, target: string): Plugin {
  return {
    name: 'pulab-embed-script',
    apply: 'build',
    async generateBundle() {
      this.emitFile({ type: 'asset', fileName: 'embed.js', source: await buildEmbed(entry, target) });
    },
  };
}
