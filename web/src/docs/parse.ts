/**
 * Chapter parser shared by the site's renderer and tests/web/docs.test.ts.
 *
 * Chapters (docs/zh/*.md, docs/en/*.md) are Markdown with these extras:
 *   - headings carry explicit, language-independent anchors:  `## Title {#anchor}`
 *   - KaTeX math: `$…$` (inline) and `$$…$$` (display, may span lines); `\$` is a literal dollar
 *   - live placeholders: `{{path}}` (a report value by JSON path, e.g. `{{vendor.Rpm.value}}`),
 *     `{{panel:NAME}}` (embed a panel), `{{plot:NAME}}` (embed a plot), `{{figure:NAME}}` (a concept
 *     figure drawn with the report's numbers, web/src/figures/concepts.ts)
 *   - links back to a panel: `[text](#panel=NAME)`
 * Fenced code blocks (```) and inline code spans (`…`) are opaque: nothing inside them is parsed.
 *
 * API:
 *   parseChapter(md) -> {
 *     headings:     {level, text, anchor}[]   anchor = '' when the heading has none
 *     math:         {tex, display, start, end}[]  start/end = offsets of the delimited span in md
 *     placeholders: string[]   report paths, in order of appearance (with repeats)
 *     panels:       string[]   panel names used by {{panel:…}} and (#panel=…) links
 *     plots:        string[]   plot names used by {{plot:…}}
 *     figures:      string[]   figure names used by {{figure:…}}
 *   }
 *   fillPlaceholders(text, value) -> text with every `{{path}}` (not panel:/plot:) replaced by
 *     value(path); use it on math before KaTeX and on prose before Markdown (panel:/plot:/figure: stay).
 */

export interface Heading {
  level: number;
  text: string;
  anchor: string;
}

export interface MathSpan {
  tex: string;
  display: boolean;
  start: number;
  end: number;
}

export interface Chapter {
  headings: Heading[];
  math: MathSpan[];
  placeholders: string[];
  panels: string[];
  plots: string[];
  figures: string[];
}

const HEADING_RE = /^(#{1,6})[ \t]+(.*?)[ \t]*(?:\{#([A-Za-z0-9_-]+)\})?[ \t]*$/;
const TOKEN_RE = /\{\{\s*([^{}\s]+)\s*\}\}/g;
const PANEL_LINK_RE = /\]\(#panel=([A-Za-z0-9_-]+)\)/g;

/** Offsets [start, end) of fenced code blocks and inline code spans. */
function codeRanges(md: string): Array<[number, number]> {
  const ranges: Array<[number, number]> = [];
  const fence = /^(```|~~~)[^\n]*\n[\s\S]*?^\1[ \t]*$/gm;
  let m: RegExpExecArray | null;
  while ((m = fence.exec(md)) !== null) ranges.push([m.index, m.index + m[0].length]);
  const inFence = (i: number) => ranges.some(([a, b]) => i >= a && i < b);
  const inline = /(`+)[^`\n][\s\S]*?\1/g;
  const spans: Array<[number, number]> = [];
  while ((m = inline.exec(md)) !== null) {
    if (!inFence(m.index)) spans.push([m.index, m.index + m[0].length]);
  }
  return ranges.concat(spans).sort((a, b) => a[0] - b[0]);
}

/** The text with code replaced by spaces (offsets preserved), so later scans ignore it. */
function blankCode(md: string): string {
  let out = '';
  let pos = 0;
  for (const [a, b] of codeRanges(md)) {
    if (a < pos) continue;
    out += md.slice(pos, a) + md.slice(a, b).replace(/[^\n]/g, ' ');
    pos = b;
  }
  return out + md.slice(pos);
}

function scanMath(text: string): MathSpan[] {
  const spans: MathSpan[] = [];
  let i = 0;
  while (i < text.length) {
    const c = text[i];
    if (c === '\\' && text[i + 1] === '$') {
      i += 2;
      continue;
    }
    if (c !== '$') {
      i++;
      continue;
    }
    if (text[i + 1] === '$') {
      const close = text.indexOf('$$', i + 2);
      if (close < 0) throw new Error(`unclosed $$ at offset ${i}`);
      spans.push({ tex: text.slice(i + 2, close).trim(), display: true, start: i, end: close + 2 });
      i = close + 2;
      continue;
    }
    let j = i + 1;
    while (j < text.length) {
      if (text[j] === '\\') {
        j += 2;
        continue;
      }
      if (text[j] === '$') break;
      if (text[j] === '\n' && text[j + 1] === '\n') throw new Error(`unclosed $ at offset ${i}`);
      j++;
    }
    if (j >= text.length) throw new Error(`unclosed $ at offset ${i}`);
    spans.push({ tex: text.slice(i + 1, j), display: false, start: i, end: j + 1 });
    i = j + 1;
  }
  return spans;
}

export function parseChapter(md: string): Chapter {
  const src = md.replace(/\r\n/g, '\n');
  const text = blankCode(src);
  const headings: Heading[] = [];
  let inFence = false;
  for (const line of src.split('\n')) {
    if (/^(```|~~~)/.test(line)) inFence = !inFence;
    if (inFence) continue;
    const m = HEADING_RE.exec(line);
    if (m) headings.push({ level: m[1].length, text: m[2], anchor: m[3] ?? '' });
  }
  const placeholders: string[] = [];
  const panels: string[] = [];
  const plots: string[] = [];
  const figures: string[] = [];
  for (const m of text.matchAll(TOKEN_RE)) {
    const tok = m[1];
    if (tok.startsWith('panel:')) panels.push(tok.slice(6));
    else if (tok.startsWith('plot:')) plots.push(tok.slice(5));
    else if (tok.startsWith('figure:')) figures.push(tok.slice(7));
    else placeholders.push(tok);
  }
  for (const m of text.matchAll(PANEL_LINK_RE)) panels.push(m[1]);
  return { headings, math: scanMath(text), placeholders, panels, plots, figures };
}

export function fillPlaceholders(text: string, value: (path: string) => string): string {
  return text.replace(TOKEN_RE, (whole, tok: string) =>
    /^(panel|plot|figure):/.test(tok) ? whole : value(tok),
  );
}
