// A tiny static server for dist/ that behaves like a well-configured production server (README,
// "Serving"): correct MIME types, the README's CSP as an HTTP header, the site mounted at any
// sub-path prefix (e.g. /tools/pu-lab/), the build's precompressed twins (.zst, .br, .gz) sent by
// Accept-Encoding, validators (ETag, Last-Modified → 304), and long caching of hashed files only.
import { createServer } from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import { extname, join, normalize } from 'node:path';

export const CSP =
  "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; worker-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data:; font-src 'self' data:";

const MIME = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.css': 'text/css', '.json': 'application/json', '.wasm': 'application/wasm', '.zip': 'application/zip',
  '.woff2': 'font/woff2', '.woff': 'font/woff', '.ttf': 'font/ttf', '.svg': 'image/svg+xml', '.png': 'image/png',
  '.bin': 'application/octet-stream',
};

/** Files whose name carries a content hash (Vite's assets/, the snapshot) never change under that name. */
export const HASHED = /(^|\/)(assets\/.*-[\w-]{8,}\.\w+|pyodide\/snapshot-[0-9a-f]{12}\.bin)$/;

/** Files other origins' pages load directly (not through a frame of this site); as a module script, with CORS. */
export const CROSS_ORIGIN = /^embed\.js$/;

/** Which stored variant to send: zstd, then brotli, then gzip, then the file itself. */
async function variant(file, acceptEncoding) {
  const accepts = (enc) => new RegExp(`(^|[,\\s])${enc}(;q=(?!0(\\.0*)?(,|$))[\\d.]+)?(,|$|\\s)`).test(acceptEncoding ?? '');
  for (const [enc, ext] of [['zstd', '.zst'], ['br', '.br'], ['gzip', '.gz']]) {
    if (!accepts(enc)) continue;
    const s = await stat(file + ext).catch(() => null);
    if (s?.isFile()) return { path: file + ext, stat: s, encoding: enc };
  }
  const s = await stat(file);
  if (!s.isFile()) throw new Error('not a file');
  return { path: file, stat: s, encoding: null };
}

/**
 * Serve `root` under `prefix` ('/' or '/a/b/'); resolves to {server, url}. Counts served bytes in
 * `server.bytesSent`. Fault injection for tests: `faults.hold(rel)` may return a promise the
 * response waits for; `faults.refuse` (RegExp) answers 404 for matching paths,
 * `faults.corrupt` (RegExp) 4 KiB of junk. `faults.cors: false` sends no Access-Control-Allow-Origin
 * (a server whose headers the docs team cannot set: only the classic `<script src>` of embed.js works).
 * `faults.extra` ({rel: [contentType, text]}): files served as if they were in `root` (the
 * benchmark's floor page), with the same headers.
 */
export function serve(root, prefix = '/', port = 0, faults = {}) {
  const server = createServer(async (req, res) => {
    const url = new URL(req.url, 'http://x');
    if (!url.pathname.startsWith(prefix)) {
      res.writeHead(404).end('not under ' + prefix);
      return;
    }
    let rel = decodeURIComponent(url.pathname.slice(prefix.length)) || 'index.html';
    if (rel.endsWith('/')) rel += 'index.html';
    await faults.hold?.(rel);
    if (faults.refuse?.test(rel)) return res.writeHead(404, { 'Content-Type': 'text/plain' }).end('refused (test)');
    if (faults.corrupt?.test(rel)) return res.writeHead(200, { 'Content-Type': 'application/octet-stream' }).end(Buffer.alloc(4096, 7));
    const extra = faults.extra?.[rel];
    if (extra) return res.writeHead(200, { 'Content-Type': extra[0], 'Content-Security-Policy': CSP, 'Cache-Control': 'no-cache' }).end(extra[1]);
    const file = normalize(join(root, rel));
    if (!file.startsWith(normalize(root))) return res.writeHead(403).end();
    try {
      const v = await variant(file, req.headers['accept-encoding']);
      const etag = `"${v.stat.size.toString(36)}-${Math.floor(v.stat.mtimeMs).toString(36)}${v.encoding ? `-${v.encoding}` : ''}"`;
      const headers = {
        'Content-Type': MIME[extname(file)] ?? 'application/octet-stream',
        'Content-Security-Policy': CSP,
        'Cache-Control': HASHED.test(rel) ? 'public, max-age=31536000, immutable' : 'no-cache',
        ETag: etag,
        'Last-Modified': v.stat.mtime.toUTCString(),
        Vary: 'Accept-Encoding',
        // embed.js as a module script of another origin's page is fetched with CORS (docs/deploy.md).
        ...(faults.cors !== false && CROSS_ORIGIN.test(rel) ? { 'Access-Control-Allow-Origin': '*' } : {}),
        ...(v.encoding ? { 'Content-Encoding': v.encoding } : {}),
      };
      const inm = req.headers['if-none-match'];
      const ims = req.headers['if-modified-since'];
      const fresh = inm ? inm.split(',').some((t) => t.trim() === etag) : ims ? Math.floor(v.stat.mtimeMs / 1000) <= Math.floor(Date.parse(ims) / 1000) : false;
      if (fresh) {
        res.writeHead(304, headers).end();
        return;
      }
      const body = await readFile(v.path);
      server.bytesSent = (server.bytesSent ?? 0) + body.length;
      res.writeHead(200, { ...headers, 'Content-Length': body.length });
      res.end(req.method === 'HEAD' ? undefined : body);
    } catch {
      res.writeHead(404, { 'Content-Type': 'text/plain' }).end('not found');
    }
  });
  return new Promise((resolve) => {
    server.listen(port, '127.0.0.1', () => {
      resolve({ server, url: `http://127.0.0.1:${server.address().port}${prefix}` });
    });
  });
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const root = process.argv[2] ?? 'dist';
  const prefix = process.argv[3] ?? '/';
  const { url } = await serve(root, prefix, Number(process.env.PORT ?? 8080));
  console.log(`serving ${root} at ${url}`);
}
