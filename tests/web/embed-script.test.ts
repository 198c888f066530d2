// dist/embed.js is one classic script (web/build/embed.ts) that finds the pu-lab site from its own
// tag in both forms: `<script src>` (document.currentScript) and `<script type="module" src>`
// (currentScript is null there: the first module tag whose src ends in /embed.js). Run here in
// happy-dom; the e2e suite `embed` runs both forms in Chromium from another origin.
import { beforeAll, describe, expect, it } from 'vitest';
import { Script } from 'node:vm';
import { resolve } from 'node:path';
import { Window } from 'happy-dom';
import { buildEmbed } from '../../web/build/embed';

let code = '';
beforeAll(async () => {
  code = await buildEmbed(resolve(__dirname, '../../web/src/embed/element.ts'), 'es2022');
});

/** A host page holding `head` and one vendor panel; embed.js run in it with `current` as document.currentScript. */
function run(head: string, current: string | null): { window: Window; frameSrc: () => string | undefined; error: unknown } {
  const window = new Window({ url: 'https://docs.example/notes/page.html' });
  const document = window.document;
  document.write(`<!doctype html><html><head>${head}</head><body><pu-lab-panel panel="vendor" lang="en"></pu-lab-panel></body></html>`);
  const cur = current === null ? null : Array.from(document.querySelectorAll('script')).find((s) => s.getAttribute('src') === current) ?? null;
  Object.defineProperty(document, 'currentScript', { configurable: true, get: () => cur });
  const names = ['window', 'document', 'customElements', 'HTMLElement', 'HTMLScriptElement', 'CustomEvent'] as const;
  let error: unknown = null;
  try {
    new Function(...names, code)(...names.map((n) => (n === 'window' ? window : (window as unknown as Record<string, unknown>)[n])));
  } catch (e) {
    error = e;
  }
  return { window, error, frameSrc: () => document.querySelector('pu-lab-panel iframe')?.getAttribute('src') ?? undefined };
}

describe('embed.js', () => {
  it('is a classic script: no import/export, no import.meta (it parses outside a module)', () => {
    expect(() => new Script(code)).not.toThrow();
    expect(code).not.toMatch(/\bimport\.meta\b|^\s*(import|export)\b/m);
  });

  it('classic tag: the site is the directory of document.currentScript', () => {
    const { frameSrc, error, window } = run('<script src="https://pu.example/tools/pu-lab/embed.js"></script>', 'https://pu.example/tools/pu-lab/embed.js');
    expect(error).toBe(null);
    expect(frameSrc()).toMatch(/^https:\/\/pu\.example\/tools\/pu-lab\/\?embed=vendor&lang=en&theme=(light|dark)$/);
    window.close();
  });

  it('module tag: the first <script type="module"> ending in /embed.js (not a classic embed.js of something else)', () => {
    const head = '<script src="https://other.example/widgets/embed.js"></script><script type="module" src="https://pu.example/pu-lab/embed.js?v=2"></script>';
    const { frameSrc, error, window } = run(head, null);
    expect(error).toBe(null);
    expect(frameSrc()).toMatch(/^https:\/\/pu\.example\/pu-lab\/\?embed=vendor&/);
    window.close();
  });

  it('without a tag to find (import()): throws, defines nothing', () => {
    const { frameSrc, error, window } = run('', null);
    expect(String(error)).toMatch(/load embed\.js with a <script src> tag/);
    expect(window.customElements.get('pu-lab-panel')).toBeUndefined();
    expect(frameSrc()).toBeUndefined();
    window.close();
  });
});
