import { describe, it, expect } from 'vitest';
import { DICTS, defaultLang, setLang, t } from '../../web/src/i18n';
import { ALL_FIELDS, SECTIONS } from '../../web/src/fields';

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
    it(`field label f.${f.path}`, () => {
      expect(DICTS.en).toHaveProperty([`f.${f.path}`]);
      expect(DICTS.zh).toHaveProperty([`f.${f.path}`]);
      for (const o of f.options ?? []) {
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
