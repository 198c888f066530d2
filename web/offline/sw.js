// pu-lab offline cache (issue 14). A template: web/offline/plugin.ts fills in VERSION (a hash of
// the whole build) and FILES (every file of the build) and emits it as dist/sw.js.
//
// Never stale after a new deployment: index.html and every file without a content hash in its
// name (Pyodide's runtime) are fetched from the network first and only taken from the cache when
// the network fails; files with a content hash (assets/name-HASH.js) are immutable, so the cache
// may serve them first. A new build has a new VERSION: the new worker installs, then deletes the
// caches of every other version.
const VERSION = '__PULAB_VERSION__';
const FILES = __PULAB_FILES__;
const CACHE = `pulab-${VERSION}`;
const SCOPE = new URL(self.registration.scope);
// The snapshot's name carries its hash too (tests/e2e/serve.mjs HASHED): never fetched again,
// never copied into the cache again on each visit (30 MB).
const HASHED = /\/(assets\/[^/]+-[A-Za-z0-9_-]{8,}\.[a-z0-9]+|pyodide\/snapshot-[0-9a-f]{12}\.bin)$/;

self.addEventListener('install', (ev) => {
  ev.waitUntil(caches.open(CACHE).then((c) => c.addAll(FILES.map((f) => new URL(f, SCOPE).href))).then(() => self.skipWaiting()));
});

self.addEventListener('activate', (ev) => {
  ev.waitUntil(caches.keys()
    .then((keys) => Promise.all(keys.filter((k) => k.startsWith('pulab-') && k !== CACHE).map((k) => caches.delete(k))))
    .then(() => self.clients.claim()));
});

self.addEventListener('fetch', (ev) => {
  const req = ev.request;
  const url = new URL(req.url);
  if (req.method !== 'GET' || url.origin !== SCOPE.origin || !url.pathname.startsWith(SCOPE.pathname)) return;
  ev.respondWith(HASHED.test(url.pathname) ? cacheFirst(req) : networkFirst(req));
});

// Never caches.open(CACHE) outside install: a worker that a new version has replaced may still be
// answering a request when the new one deletes its cache, and open() would create that cache again
// (a CI run kept the old version's cache for good that way).
async function fromCache(req) {
  const hit = await caches.match(req, { cacheName: CACHE, ignoreSearch: true });
  if (hit || req.mode !== 'navigate') return hit;
  return caches.match(new URL('index.html', SCOPE).href, { cacheName: CACHE });
}

async function store(req, res) {
  if (await caches.has(CACHE)) await (await caches.open(CACHE)).put(req, res);
}

async function networkFirst(req) {
  try {
    const res = await fetch(req);
    if (res.ok && !res.redirected) {
      void store(req, res.clone()).catch(() => undefined);
    }
    return res;
  } catch (e) {
    const hit = await fromCache(req);
    if (hit) return hit;
    throw e;
  }
}

async function cacheFirst(req) {
  return (await fromCache(req)) ?? networkFirst(req);
}
