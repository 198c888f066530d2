// Where the numbers on screen come from, published as <html data-numbers> (contract:
// docs/contract.md, "Instant start"):
//   build  — the seed report prerendered by CPython at build time, for the input in the form;
//   cached — a report kept in localStorage from an earlier visit, for the input in the form;
//   live   — computed by Python in this page for the input now in the form;
//   stale  — numbers on screen are of an earlier input (typing, an error, Python not ready yet);
//   none   — no numbers yet.
import { PULAB_HASH, SEED_KEY, SEED_RESULT } from 'virtual:pulab-build';
import type { Report } from '../generated/report-types';
import { load, store } from './storage';

export type NumbersSource = 'none' | 'build' | 'cached' | 'live' | 'stale';

const CACHE_KEY = 'pulab.reports.v1';
/** Reports kept (newest first): the last input of the page and of a few embeds. */
const CACHE_SIZE = 8;
type Cache = { pulab: string; entries: [string, Report][] };

function readCache(): Cache {
  try {
    const c = JSON.parse(load(CACHE_KEY) ?? 'null') as Cache | null;
    // Reports of another pulab (a new deployment) may differ: not reused.
    if (c && c.pulab === PULAB_HASH && Array.isArray(c.entries)) return c;
  } catch {
    /* a corrupt entry is replaced */
  }
  return { pulab: PULAB_HASH, entries: [] };
}

/** A report known without Python: the build's seed report, or one cached by an earlier visit. */
export function knownReport(key: string): { report: Report; source: 'build' | 'cached' } | null {
  if (key === SEED_KEY) {
    const r = JSON.parse(SEED_RESULT) as { ok: boolean; report?: Report };
    if (r.ok && r.report) return { report: r.report, source: 'build' };
  }
  const hit = readCache().entries.find(([k]) => k === key);
  return hit && hit[1] && typeof hit[1] === 'object' ? { report: hit[1], source: 'cached' } : null;
}

let pending: [string, Report] | null = null;
let timer: ReturnType<typeof setTimeout> | undefined;
/** Keep a live report for the next visit (written after a pause: typing makes many). */
export function keepReport(key: string, report: Report): void {
  if (key === SEED_KEY) return;
  pending = [key, report];
  clearTimeout(timer);
  timer = setTimeout(() => {
    if (!pending) return;
    const c = readCache();
    const [k, r] = pending;
    pending = null;
    c.entries = [[k, r] as [string, Report], ...c.entries.filter(([x]) => x !== k)].slice(0, CACHE_SIZE);
    store(CACHE_KEY, JSON.stringify(c));
  }, 1000);
}

export function showSource(source: NumbersSource): void {
  const root = document.documentElement;
  root.dataset.numbers = source;
  // Build or cached numbers on screen (dashed panels): a class that changes only when that does.
  const prelive = source === 'build' || source === 'cached';
  if (root.classList.contains('prelive-numbers') !== prelive) root.classList.toggle('prelive-numbers', prelive);
}
