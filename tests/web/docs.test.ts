// The explainer chapters (docs/zh, docs/en, docs/index.json):
// (a) zh and en have the same files, heading levels and anchor ids;
// (b) every formula renders with KaTeX (placeholders inside math replaced by a number);
// (c) every {{path}} placeholder resolves to a number or string in every golden report;
// (d) panel names used exist in index.json, and every index.json anchor exists in both languages.
import { readFileSync, readdirSync, existsSync } from 'node:fs';
import { join, resolve } from 'node:path';
import katex from 'katex';
import { describe, expect, it } from 'vitest';
import { fillPlaceholders, parseChapter, type Chapter } from '../../web/src/docs/parse';
import schema from '../../web/src/generated/schema.json';

const ROOT = resolve(__dirname, '../..');
const DOCS = join(ROOT, 'docs');
const LANGS = ['zh', 'en'] as const;
const PANELS = ['inputs', 'bases', 'pu', 'vendor', 'constants', 'current', 'pll', 'qcalc', 'conventions', 'vendors', 'sweep', 'batch', 'prove', 'code', 'loop', 'board', 'fw', 'observer'];
const PLOTS = ['current', 'pll'];

interface Index {
  chapters: { id: string; file: string; title: { zh: string; en: string } }[];
  panels: Record<string, string>;
}

const index: Index = JSON.parse(readFileSync(join(DOCS, 'index.json'), 'utf8'));
const mdFiles = (lang: string) =>
  readdirSync(join(DOCS, lang))
    .filter((f) => f.endsWith('.md'))
    .sort();
const chapters: Record<string, Record<string, Chapter>> = {};
for (const lang of LANGS) {
  chapters[lang] = {};
  for (const f of mdFiles(lang)) chapters[lang][f] = parseChapter(readFileSync(join(DOCS, lang, f), 'utf8'));
}

describe('docs: structure', () => {
  it('index.json lists exactly the chapter files, with both titles', () => {
    const files = index.chapters.map((c) => c.file).sort();
    expect(files.length).toBeGreaterThan(0);
    for (const lang of LANGS) expect(mdFiles(lang)).toEqual(files);
    for (const c of index.chapters) {
      expect(c.file).toBe(`${c.id}.md`);
      expect(c.title.zh.length).toBeGreaterThan(0);
      expect(c.title.en.length).toBeGreaterThan(0);
    }
  });

  for (const f of mdFiles('en')) {
    it(`${f}: zh and en have the same heading levels and anchors`, () => {
      const en = chapters.en[f].headings.map((h) => [h.level, h.anchor]);
      const zh = (chapters.zh[f]?.headings ?? []).map((h) => [h.level, h.anchor]);
      expect(zh).toEqual(en);
      expect(en.length).toBeGreaterThan(1);
      expect(en[0][0]).toBe(1);
    });
  }

  it('every heading has an anchor, unique across all chapters of a language', () => {
    for (const lang of LANGS) {
      const seen = new Set<string>();
      for (const [f, ch] of Object.entries(chapters[lang])) {
        for (const h of ch.headings) {
          expect(h.anchor, `${lang}/${f}: "${h.text}"`).toMatch(/^[a-z0-9][a-z0-9-]*$/);
          expect(seen.has(h.anchor), `${lang}/${f}: duplicate #${h.anchor}`).toBe(false);
          seen.add(h.anchor);
        }
      }
    }
  });

  it('zh and en use the same placeholders, panels and plots per chapter', () => {
    for (const f of mdFiles('en')) {
      const uniq = (xs: string[]) => [...new Set(xs)].sort();
      for (const k of ['placeholders', 'panels', 'plots'] as const) {
        expect(uniq(chapters.zh[f][k]), `${f} ${k}`).toEqual(uniq(chapters.en[f][k]));
      }
    }
  });
});

describe('docs: formulas render', () => {
  for (const lang of LANGS) {
    for (const f of mdFiles(lang)) {
      it(`${lang}/${f}`, () => {
        const ch = chapters[lang][f];
        expect(ch.math.length).toBeGreaterThan(0);
        for (const m of ch.math) {
          const tex = fillPlaceholders(m.tex, () => '-1234.5678');
          expect(() => katex.renderToString(tex, { throwOnError: true, strict: 'error', displayMode: m.display }), tex).not.toThrow();
        }
      });
    }
  }
});

describe('docs: placeholders resolve in every golden report', () => {
  const goldenDir = join(ROOT, 'tests', 'golden');
  const goldens = existsSync(goldenDir)
    ? readdirSync(goldenDir)
        .filter((f) => f.endsWith('.json'))
        .sort()
    : [];

  it('golden reports exist', () => {
    expect(goldens.length, 'tests/golden/*.json is empty: the placeholder check would be vacuous').toBeGreaterThan(0);
  });

  const paths = new Set<string>();
  for (const lang of LANGS) for (const ch of Object.values(chapters[lang])) ch.placeholders.forEach((p) => paths.add(p));

  it('the chapters use placeholders', () => {
    expect(paths.size).toBeGreaterThan(10);
  });

  const lookup = (obj: unknown, path: string): unknown =>
    path.split('.').reduce<unknown>((o, k) => (o !== null && typeof o === 'object' ? (o as Record<string, unknown>)[k] : undefined), obj);

  // loop.robust.* comes with the simulation request: resolved in the robustness vectors
  // (tests/golden/robust, expected = {cases}) instead of the plain report vectors.
  const robustPaths = [...paths].filter((p) => p.startsWith('loop.robust.'));
  const robustDir = join(goldenDir, 'robust');
  const robustGoldens = existsSync(robustDir) ? readdirSync(robustDir).filter((f) => f.endsWith('.json')).sort() : [];
  it('robustness vectors exist for the chapters\' loop.robust placeholders', () => {
    expect(robustPaths.length === 0 || robustGoldens.length > 0).toBe(true);
  });
  for (const g of robustGoldens) {
    it(`robust/${g}`, () => {
      const doc = JSON.parse(readFileSync(join(robustDir, g), 'utf8'));
      for (const p of robustPaths) {
        const v = lookup({ loop: { robust: doc.expected } }, p);
        expect(typeof v === 'number' && Number.isFinite(v), `robust/${g}: {{${p}}} -> ${JSON.stringify(v)}`).toBe(true);
      }
    });
  }

  // input.* echoes the normalized input (defaults filled in, docs/contract.md): the golden files
  // leave it out, so each such placeholder must name a field of the schema.
  it('input.* placeholders name input fields', () => {
    const fields = new Set(JSON.stringify(schema).match(/"path":\s*"[^"]+"/g)?.map((m) => m.replace(/^"path":\s*"|"$/g, '')) ?? []);
    expect(fields.size).toBeGreaterThan(10);
    for (const p of paths) if (p.startsWith('input.')) expect(fields.has(p.slice(6)), p).toBe(true);
  });

  for (const g of goldens) {
    it(g, () => {
      const doc = JSON.parse(readFileSync(join(goldenDir, g), 'utf8'));
      if (!('expected' in doc)) return; // not a report vector (e.g. a simulation trajectory file)
      // A motor the Inovance firmware cannot hold has no vendor integers: the chapters show
      // '…' there, and firmware.inovance says why (at least one problem must be named).
      const cannotHold = lookup(doc.expected, 'firmware.inovance.representable') === false;
      if (cannotHold) expect((lookup(doc.expected, 'firmware.inovance.problems') as unknown[]).length).toBeGreaterThan(0);
      for (const p of paths) {
        if (p.startsWith('loop.robust.') || p.startsWith('input.')) continue;
        const v = lookup(doc.expected, p);
        if (cannotHold && p.startsWith('vendor.') && v === undefined) continue;
        const ok = (typeof v === 'number' && Number.isFinite(v)) || typeof v === 'string';
        expect(ok, `${g}: {{${p}}} -> ${JSON.stringify(v)}`).toBe(true);
      }
    });
  }

  it('at least one golden file is a report vector', () => {
    const reports = goldens.filter((g) => 'expected' in JSON.parse(readFileSync(join(goldenDir, g), 'utf8')));
    expect(reports.length).toBeGreaterThan(0);
  });
});

describe('docs: panel links', () => {
  it('index.json maps every panel of the site', () => {
    expect(Object.keys(index.panels).sort()).toEqual([...PANELS].sort());
  });

  it('every index.json anchor exists in both languages', () => {
    for (const [panel, target] of Object.entries(index.panels)) {
      const [id, anchor] = target.split('#');
      const file = `${id}.md`;
      for (const lang of LANGS) {
        const ch = chapters[lang][file];
        expect(ch, `${panel} -> ${lang}/${file}`).toBeDefined();
        expect(ch.headings.map((h) => h.anchor), `${panel} -> ${lang}/${target}`).toContain(anchor);
      }
    }
  });

  it('every panel and plot used by a chapter exists', () => {
    for (const lang of LANGS) {
      for (const [f, ch] of Object.entries(chapters[lang])) {
        for (const p of ch.panels) expect(Object.keys(index.panels), `${lang}/${f}: panel ${p}`).toContain(p);
        for (const p of ch.plots) expect(PLOTS, `${lang}/${f}: plot ${p}`).toContain(p);
      }
    }
  });

  it('every chapter ends with a link back to a panel', () => {
    for (const lang of LANGS) {
      for (const f of mdFiles(lang)) {
        const md = readFileSync(join(DOCS, lang, f), 'utf8').trimEnd();
        const last = md.split('\n').pop() ?? '';
        expect(last, `${lang}/${f}`).toMatch(/\[[^\]]+\]\(#panel=[a-z]+\)$/);
      }
    }
  });
});
