// Every label, unit and message in Chinese and English, each feature's in its own file under i18n/
// (a new feature adds a file and one line below; the compiler checks zh has every key).
import page from './i18n/page';
import form from './i18n/form';
import report from './i18n/report';
import sim from './i18n/sim';
import family from './i18n/family';
import code from './i18n/code';
import vendors from './i18n/vendors';
import loop from './i18n/loop';
import review from './i18n/review';
import qcalc from './i18n/qcalc';
import screens from './i18n/screens';
import datasheet from './i18n/datasheet';
import ctrace from './i18n/ctrace';
import prove from './i18n/prove';
import course from './i18n/course';
import simfirmware from './i18n/simfirmware';
import codeprove from './i18n/codeprove';
import audit from './i18n/audit';
import acim from './i18n/acim';
import codeloop from './i18n/codeloop';
import codeseq from './i18n/codeseq';

export type Lang = 'en' | 'zh';

const en = { ...page.en, ...form.en, ...report.en, ...sim.en, ...family.en, ...code.en, ...vendors.en, ...loop.en, ...review.en, ...qcalc.en,
  ...screens.en, ...datasheet.en,
  ...ctrace.en, ...prove.en, ...course.en, ...simfirmware.en, ...codeprove.en, ...audit.en, ...acim.en, ...codeloop.en, ...codeseq.en };

export type Key = keyof typeof en;

const zh: Record<Key, string> = {
  ...page.zh,
  ...form.zh,
  ...report.zh,
  ...sim.zh,
  ...family.zh,
  ...code.zh,
  ...vendors.zh,
  ...loop.zh,
  ...review.zh,
  ...qcalc.zh,
  ...screens.zh,
  ...datasheet.zh,
  ...ctrace.zh,
  ...prove.zh,
  ...course.zh,
  ...simfirmware.zh,
  ...codeprove.zh,
  ...audit.zh,
  ...acim.zh,
  ...codeloop.zh,
  ...codeseq.zh,
};

export const DICTS: Record<Lang, Record<Key, string>> = { en, zh };

let lang: Lang = 'en';

export function defaultLang(navLanguages: readonly string[] | undefined, stored: string | null): Lang {
  if (stored === 'en' || stored === 'zh') return stored;
  for (const l of navLanguages ?? []) {
    if (/^zh\b/i.test(l)) return 'zh';
    if (/^en\b/i.test(l)) return 'en';
  }
  return 'en';
}

export function setLang(l: Lang): void {
  lang = l;
}
/** A pulab message in the reader's language (Python sends English and Chinese). */
export function errText(e: { message?: string; message_zh?: string }): string {
  return (lang === 'zh' && e.message_zh ? e.message_zh : e.message) ?? '';
}

export function getLang(): Lang {
  return lang;
}

/** Translate `key`, substituting {name} placeholders. */
export function t(key: Key, vars: Record<string, string | number> = {}): string {
  const s = DICTS[lang][key] ?? en[key] ?? key;
  return s.replace(/\{(\w+)\}/g, (_, k: string) => String(vars[k] ?? `{${k}}`));
}

export function has(key: string): key is Key {
  return key in en;
}
