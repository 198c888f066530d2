// @vitest-environment happy-dom
// The course markup (docs/render.ts): exercises and the goals / summary / common-mistakes boxes.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { renderMarkdown } from '../../web/src/docs/render';

const render = (md: string) => {
  const el = document.createElement('div');
  el.innerHTML = renderMarkdown(md, { value: (p) => (p === 'base.U_b' ? 9.81 : undefined) });
  return el;
};

describe('course markup', () => {
  it('an exercise has data-exercise, an answer field exercise.ID, a hidden hint and a solution', () => {
    const el = render('Text.\n\n::: exercise warmup-ub\nWhat is $U_b$?\n::: hint\nLine vs phase.\n::: solution\n$U_b$ = {{base.U_b}} V.\n:::\n\nAfter.');
    const ex = el.querySelector<HTMLElement>('[data-exercise="warmup-ub"]')!;
    expect(ex).not.toBeNull();
    expect(ex.querySelector('input[name="exercise.warmup-ub"]')).not.toBeNull();
    expect(ex.querySelector('.ex-hint')?.hasAttribute('hidden')).toBe(true);
    expect(ex.querySelector('.ex-hint')?.textContent).toContain('Line vs phase.');
    expect(ex.querySelector('details.ex-solution [data-key="base.U_b"]')?.getAttribute('data-value')).toBe('9.81');
    expect(ex.querySelector('.ex-q .katex')).not.toBeNull();
    expect(el.querySelector(':scope > p:last-child')?.textContent).toBe('After.');
  });
  it('a choice exercise is a select with the listed values; trace adds the tracer button', () => {
    const el = render('::: exercise pll-naive-locks choice yes no\nLocks?\n:::\n\n::: exercise vendor-bug trace\nRun:\n\n```c\nRpm = 1;\n```\n:::');
    const opts = [...el.querySelectorAll<HTMLOptionElement>('select[name="exercise.pll-naive-locks"] option')].map((o) => o.value);
    expect(opts).toEqual(['', 'yes', 'no']);
    expect(el.querySelector('[data-exercise="vendor-bug"] [data-ex-trace]')).not.toBeNull();
    expect(el.querySelector('[data-exercise="vendor-bug"] .ex-q pre code')?.textContent).toBe('Rpm = 1;');
  });
  it('boxes get their class', () => {
    const el = render('> **Goals** — a\n\n> **小结** — b\n\n> **Common mistakes** — c\n\n> **Erratum** — d');
    expect([...el.querySelectorAll('blockquote')].map((b) => b.className)).toEqual(
      ['doc-note goals', 'doc-note summary', 'doc-note mistakes', 'doc-note erratum']);
  });
  it('every day-one chapter has goals, common mistakes and a summary in both languages', () => {
    const course = JSON.parse(readFileSync(resolve(__dirname, '../../docs/course.json'), 'utf8')) as { day_one: { chapters: string[] }[] };
    for (const lang of ['en', 'zh']) {
      for (const id of course.day_one.flatMap((s) => s.chapters)) {
        const el = render(readFileSync(resolve(__dirname, `../../docs/${lang}/${id}.md`), 'utf8'));
        for (const c of ['goals', 'mistakes', 'summary']) expect(el.querySelectorAll(`blockquote.${c}`).length, `${lang}/${id} ${c}`).toBe(1);
        expect(el.querySelectorAll('[data-exercise]').length, `${lang}/${id}`).toBeGreaterThanOrEqual(5);
      }
    }
  });
});

describe('concept figures', () => {
  const value = (p: string) => ({ 'base.I_b': 1.5, 'base.U_b': 9.815, 'pll.kp_pu': 1.0097, 'pll.ki_pu': 224.3, 'pll.integrator_gain': 440,
    'vendor.LD.value': 1045, 'current_pi.d.pm_kp': 1180, 'current_pi.d.pm_ki': 4720 } as Record<string, number>)[p];
  it('each named figure is an SVG with the reader\'s numbers as data-key/data-value', async () => {
    const { FIGURES } = await import('../../web/src/figures/concepts');
    for (const name of FIGURES) {
      const el = document.createElement('div');
      el.innerHTML = renderMarkdown(`{{figure:${name}}}`, { value });
      const fig = el.querySelector(`figure[data-figure="${name}"] svg`);
      expect(fig, name).not.toBeNull();
      expect(el.querySelectorAll('[data-key][data-value]').length, name).toBeGreaterThan(0);
    }
    const el = document.createElement('div');
    el.innerHTML = renderMarkdown('{{figure:qbits}}', { value });
    // LD = 1045 = 0b0000010000010101 in the 16 bit cells
    const bits = [...el.querySelectorAll('rect.fig-bit + text')].slice(0, 16).map((t) => t.textContent).join('');
    expect(bits).toBe((1045).toString(2).padStart(16, '0'));
  });
  it('the chapters name only existing figures', async () => {
    const { FIGURES } = await import('../../web/src/figures/concepts');
    const { parseChapter } = await import('../../web/src/docs/parse');
    const { readdirSync } = await import('node:fs');
    for (const lang of ['en', 'zh']) {
      for (const f of readdirSync(resolve(__dirname, `../../docs/${lang}`))) {
        for (const n of parseChapter(readFileSync(resolve(__dirname, `../../docs/${lang}/${f}`), 'utf8')).figures) expect(FIGURES, `${lang}/${f}`).toContain(n);
      }
    }
  });
});
