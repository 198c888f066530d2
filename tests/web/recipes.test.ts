// @vitest-environment happy-dom
// The page-view recipe of docs/design.md works as written: its code block, compiled as a file of
// web/src/panels, renders the seed motor's golden report with the number's path and value on the
// element; every registered panel has what the recipe asks for (a view, its texts in both languages).
import { describe, expect, it } from 'vitest';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { PANELS } from '../../web/src/panels/registry';
import { VIEWS } from '../../web/src/panels/views';
import { setLang, t, type Key } from '../../web/src/i18n';
import type { Panel, PanelContext } from '../../web/src/panels/panel';
import type { Report } from '../../web/src/generated/report-types';

// (happy-dom gives import.meta.url an http: scheme; vitest runs from the repository root)
const ROOT = process.cwd();

function recipe(title: string): string {
  const text = readFileSync(join(ROOT, 'docs/design.md'), 'utf8');
  const at = text.indexOf(`**${title}**`);
  expect(at).toBeGreaterThan(0);
  return /```ts\n([\s\S]*?)```/.exec(text.slice(at))![1];
}

describe('docs/design.md "Adding a page view"', () => {
  it('the example panel renders its number with data-key and data-value', async () => {
    // the block's imports are relative to web/src/panels: made absolute for a file outside it
    const src = recipe('Adding a page view').replace(/from '\.\.?\/([^']+)'/g, (_, p: string) =>
      `from '${join(ROOT, 'web/src', p.startsWith('panel') ? `panels/${p}` : p)}'`);
    // inside the repository: the test runner compiles only files under its root
    const dir = mkdtempSync(join(ROOT, 'tests/web/.recipe-'));
    try {
      writeFileSync(join(dir, 'impedance.ts'), src);
      const mod = (await import(/* @vite-ignore */ join(dir, 'impedance.ts'))) as Record<string, Panel>;
      const panel = Object.values(mod)[0];
      expect(panel.id).toBe('impedance');
      const gold = JSON.parse(readFileSync(join(ROOT, 'tests/golden/01_seed_motor.json'), 'utf8')) as { expected: Report };
      const el = document.createElement('section');
      const ctx: PanelContext = { report: gold.expected, simReport: null, simError: null, input: {}, client: null, embed: false };
      panel.render(el, ctx);
      const shown = el.querySelector('[data-key="base.Z_b"]');
      expect(Number(shown?.getAttribute('data-value'))).toBe(gold.expected.base.Z_b);
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });

  it('every registered panel is in a view and has its title and tab texts in both languages', () => {
    const listed = new Set(VIEWS.flatMap((v) => v.panels));
    for (const lang of ['en', 'zh'] as const) {
      setLang(lang);
      for (const p of PANELS) {
        expect(listed.has(p.id), p.id).toBe(true);
        for (const key of [p.title, `nav_${p.id}`]) expect(t(key as Key), `${lang} ${key}`).not.toBe(key);
      }
    }
    setLang('en');
  });
});
