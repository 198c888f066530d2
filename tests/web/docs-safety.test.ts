// Latent cases of the chapter renderer: chapters and report values are data, not markup.
import { describe, it, expect } from 'vitest';
import katex from 'katex';
import { renderMarkdown, safeHref, texValue } from '../../web/src/docs/render';

const render = (md: string, value: unknown = 1): string => renderMarkdown(md, { value: () => value });

describe('links: only same-page anchors and https become links', () => {
  const cases: [string, string | null][] = [
    ['#panel=bases', '#panel=bases'], ['#units', '#units'], ['https://example.org/a?b=1&c=2', 'https://example.org/a?b=1&c=2'],
    ['javascript:alert(1)', null], ['JaVaScRiPt:alert(1)', null], ['data:text/html,<b>x</b>', null], ['http://example.org', null],
    ['//example.org', null], ['https:example.org', null], ['vbscript:x', null], ['#a"onmouseover=x', null], ['./other.html', null],
  ];
  for (const [href, want] of cases) it(`${href} → ${String(want)}`, () => expect(safeHref(href)).toBe(want));

  const rendered: [string, string, RegExp][] = [
    ['javascript link stays text', '[click](javascript:alert(1))', /^<p>\[click\]\(javascript:alert\(1\)\)<\/p>$/],
    ['https link, & escaped in the attribute', '[ref](https://example.org/?a=1&b=2)', /href="https:\/\/example\.org\/\?a=1&amp;b=2" rel="noopener"/],
    ['panel link', '[see](#panel=vendor)', /href="#panel-vendor" data-panel-link="vendor"/],
  ];
  for (const [name, md, want] of rendered) it(name, () => expect(render(md)).toMatch(want));
  it('no rendered link has another scheme', () => {
    const html = render('[a](javascript:x) [b](data:x) [c](https://ok.example) [d](#ok) [e](mailto:x@y)');
    const hrefs = [...html.matchAll(/href="([^"]*)"/g)].map((m) => m[1]);
    expect(hrefs).toEqual(['https://ok.example', '#doc-ok']);
  });
});

describe('a report string inside TeX is text, never commands', () => {
  const hostile = ['\\href{javascript:alert(1)}{x}', '}\\def\\x{1}{', '$x$', 'a_b^c', '50% & #1 ~', '\\\\', '{', 'π rad'];
  for (const s of hostile)
    it(`${s} renders as text`, () => {
      const tex = `x = ${texValue(s)}`;
      const html = katex.renderToString(tex, { throwOnError: true, strict: 'ignore' }); // unicode text is fine; commands are not
      expect(html).not.toContain('<a ');
      expect(html).not.toContain('katex-error');
      const md = render(`$y = {{p}}$`, s);
      expect(md).not.toContain('katex-error');
      expect(md).not.toContain('<a ');
    });
  it('a number stays a number', () => expect(texValue(0.0732)).toBe('0.0732'));
});
