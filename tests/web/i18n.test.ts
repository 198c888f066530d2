import { describe, it, expect } from 'vitest';
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { DICTS, defaultLang, errText, has, setLang, t } from '../../web/src/i18n';
import { ALL_FIELDS, SECTIONS } from '../../web/src/fields';
import { vendorName } from '../../web/src/vendors';

describe('defaultLang: stored choice, then navigator.languages', () => {
  const cases: [string[], string | null, string][] = [
    [['zh-CN', 'en'], null, 'zh'],
    [['zh-TW'], null, 'zh'],
    [['en-US', 'zh-CN'], null, 'en'],
    [['de-DE', 'zh'], null, 'zh'],
    [['fr'], null, 'en'],
    [['zh-CN'], 'en', 'en'],
    [[], 'zh', 'zh'],
  ];
  for (const [nav, stored, want] of cases) it(`${JSON.stringify(nav)}, stored ${stored} → ${want}`, () => expect(defaultLang(nav, stored)).toBe(want));
});

describe('every label exists in both languages', () => {
  it('zh has every en key, none empty', () => {
    for (const k of Object.keys(DICTS.en)) expect(DICTS.zh[k as keyof typeof DICTS.zh], k).toBeTruthy();
  });
  for (const f of ALL_FIELDS) {
    it(`field label ${f.path}`, () => {
      expect(f.label[0]).toBeTruthy();
      expect(f.label[1]).toBeTruthy();
      for (const o of f.options ?? []) {
        if (f.path === 'conventions.firmware') { // a vendor: pulab names it (generated/schema.json)
          for (const lang of ['zh', 'en'] as const) {
            setLang(lang);
            expect(vendorName(o), `${lang} ${o}`).toBeTruthy();
          }
          continue;
        }
        expect(DICTS.en).toHaveProperty([`o.${o}`]);
        expect(DICTS.zh).toHaveProperty([`o.${o}`]);
      }
    });
  }
  for (const s of SECTIONS) it(`section ${s.id}`, () => expect(DICTS.zh[s.title]).toBeTruthy());
  it('placeholders are substituted', () => {
    setLang('zh');
    expect(t('latency', { ms: '1.5' })).toBe('上次报告 Python 耗时 1.5 ms');
    setLang('en');
    expect(t('stepExample', { e: 410 })).toContain('error = 410');
  });
});

describe('errText: Python messages in the reader language', () => {
  const e = { message: 'must be > 0, got -1', message_zh: '必须大于 0，当前为 -1' };
  const cases: ['en' | 'zh', { message?: string; message_zh?: string }, string][] = [
    ['en', e, 'must be > 0, got -1'],
    ['zh', e, '必须大于 0，当前为 -1'],
    ['zh', { message: 'only English' }, 'only English'],
    ['en', {}, ''],
  ];
  for (const [lang, msg, want] of cases) {
    it(`${lang}: ${JSON.stringify(msg)} → ${JSON.stringify(want)}`, () => {
      setLang(lang);
      expect(errText(msg)).toBe(want);
      setLang('en');
    });
  }
});

describe('the feature files under i18n/', () => {
  const files = import.meta.glob<{ default?: { en: Record<string, string>; zh: Record<string, string> } }>('../../web/src/i18n/*.ts', { eager: true });
  const dicts = Object.entries(files).filter(([, m]) => m.default).map(([name, m]) => [name, m.default!] as const);
  it('no key is defined by two files (a later spread would hide the other silently)', () => {
    const owner = new Map<string, string>();
    for (const [name, d] of dicts) {
      for (const k of Object.keys(d.en)) {
        expect(owner.get(k), `${k} in ${name}`).toBeUndefined();
        owner.set(k, name);
      }
    }
  });
  it('every file is registered in i18n.ts, and i18n.ts has no key of its own', () => {
    const keys = dicts.flatMap(([, d]) => Object.keys(d.en)).sort();
    expect(Object.keys(DICTS.en).sort()).toEqual(keys);
    expect(dicts.length).toBeGreaterThanOrEqual(10);
  });
});

describe('the field-weakening tables are described in both languages', () => {
  // every table the golden interior motors produce (tests/golden/fw_tables, written by numpy)
  const dir = join(__dirname, '../golden/fw_tables');
  const names = new Set(readdirSync(dir).filter((f) => f.endsWith('.json'))
    .flatMap((f) => Object.keys((JSON.parse(readFileSync(join(dir, f), 'utf8')) as { expected: object }).expected)));
  for (const name of [...names, 'st_mtpa', 'mtpa_id_of_iq', 'fw_id_of_speed']) {
    it(name, () => {
      expect(has(`fwTable_${name}`), name).toBe(true);
      expect(DICTS.zh[`fwTable_${name}` as keyof typeof DICTS.zh]).toMatch(/[\u4e00-\u9fff]/);
    });
  }
});
