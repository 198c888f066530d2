// The offline cache's service worker (web/offline/sw.js) run in a Node vm with an in-memory
// CacheStorage: a version that a new deployment replaced must never bring its deleted cache back
// (CI once kept the old version's cache that way: a late request answered by the old worker
// re-created it with caches.open).
import { readFileSync } from 'node:fs';
import { runInNewContext } from 'node:vm';
import { describe, expect, it } from 'vitest';

const TEMPLATE = readFileSync(new URL('../../web/offline/sw.js', import.meta.url), 'utf8');
const SCOPE = 'https://intranet.example/pu/';

/** CacheStorage in memory, keys in creation order as the spec orders them. */
function cacheStorage() {
  const stores = new Map<string, Map<string, Response>>();
  const key = (r: Request | string) => (typeof r === 'string' ? r : r.url).split('?')[0];
  const cache = (m: Map<string, Response>) => ({
    put: async (r: Request | string, res: Response) => void m.set(key(r), res),
    match: async (r: Request | string) => m.get(key(r)),
    addAll: async (urls: string[]) => urls.forEach((u) => m.set(key(u), new Response(u))),
  });
  return {
    stores,
    open: async (name: string) => {
      if (!stores.has(name)) stores.set(name, new Map());
      return cache(stores.get(name)!);
    },
    has: async (name: string) => stores.has(name),
    delete: async (name: string) => stores.delete(name),
    keys: async () => [...stores.keys()],
    match: async (r: Request | string, o: { cacheName?: string } = {}) => {
      const names = o.cacheName === undefined ? [...stores.keys()] : [o.cacheName];
      for (const n of names) {
        const hit = stores.get(n)?.get(key(r));
        if (hit) return hit;
      }
      return undefined;
    },
  };
}

/** One version of the worker: its event handlers, sharing `caches` and `network` with others. */
function version(v: string, caches: ReturnType<typeof cacheStorage>, network: { up: boolean }) {
  const handlers = new Map<string, (ev: unknown) => void>();
  const source = TEMPLATE.replace("'__PULAB_VERSION__'", JSON.stringify(v)).replace('__PULAB_FILES__', '["index.html","assets/app-abcdef12.js"]');
  const self = {
    registration: { scope: SCOPE },
    addEventListener: (t: string, f: (ev: unknown) => void) => handlers.set(t, f),
    skipWaiting: async () => undefined,
    clients: { claim: async () => undefined },
  };
  const fetch = async (r: Request) => {
    if (!network.up) throw new TypeError('offline');
    return new Response(`${r.url} from the network`);
  };
  runInNewContext(source, { self, caches, fetch, URL, Response, Request, Promise });
  const lifecycle = async (t: 'install' | 'activate') => {
    let wait: Promise<unknown> = Promise.resolve();
    handlers.get(t)!({ waitUntil: (p: Promise<unknown>) => (wait = p) });
    await wait;
  };
  const get = async (path: string) => {
    let answer: Promise<Response> | undefined;
    handlers.get('fetch')!({ request: new Request(SCOPE + path), respondWith: (p: Promise<Response>) => (answer = p) });
    const res = await answer!;
    await new Promise((r) => setTimeout(r, 0)); // let the copy into the cache finish
    return res;
  };
  return { lifecycle, get };
}

describe('offline cache service worker', () => {
  const cases: { name: string; network: boolean; path: string; keys: string[] }[] = [
    { name: 'old version answers online after the new one deleted its cache → only the new cache', network: true, path: 'pyodide/pyodide.asm.wasm', keys: ['pulab-b'] },
    { name: 'old version answers offline after the new one deleted its cache → only the new cache', network: false, path: 'index.html', keys: ['pulab-b'] },
    { name: 'old version asked for a hashed asset after the new one deleted its cache → only the new cache', network: true, path: 'assets/app-abcdef12.js', keys: ['pulab-b'] },
  ];
  it.each(cases)('$name', async ({ network, path, keys }) => {
    const caches = cacheStorage();
    const net = { up: true };
    const a = version('a', caches, net);
    await a.lifecycle('install');
    await a.lifecycle('activate');
    const b = version('b', caches, net);
    await b.lifecycle('install');
    expect(await caches.keys()).toEqual(['pulab-a', 'pulab-b']);
    await b.lifecycle('activate');
    net.up = network;
    await a.get(path).catch(() => undefined);
    expect(await caches.keys()).toEqual(keys);
  });

  it('current version online → the response is copied into its cache and served offline later', async () => {
    const caches = cacheStorage();
    const net = { up: true };
    const a = version('a', caches, net);
    await a.lifecycle('install');
    await a.lifecycle('activate');
    expect(await (await a.get('pyodide/pyodide.asm.wasm')).text()).toBe(`${SCOPE}pyodide/pyodide.asm.wasm from the network`);
    net.up = false;
    expect(await (await a.get('pyodide/pyodide.asm.wasm')).text()).toBe(`${SCOPE}pyodide/pyodide.asm.wasm from the network`);
    expect(await (await a.get('index.html')).text()).toBe(`${SCOPE}index.html`);
  });
});
