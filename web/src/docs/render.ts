// Markdown (the subset the chapters use) → HTML, with KaTeX math, live report values
// ({{path}} → a number with data-key) and panel/plot embeds ({{panel:NAME}}, {{plot:NAME}}).
import katex from 'katex';
import { fillPlaceholders } from './parse';
import { fmtNum } from '../format';
import { has, t } from '../i18n';
import { drawFigure, isFigure } from '../figures/concepts';

export const esc = (s: string): string =>
  s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

const KATEX_CACHE = new Map<string, string>();

export interface RenderOpts {
  /** Value at a report path (undefined when absent). */
  value(path: string): unknown;
}

/** Text shown for a report value inside math and prose. */
export function valueText(v: unknown): string {
  if (typeof v === 'number') return fmtNum(v, 6);
  if (typeof v === 'string') return v;
  if (typeof v === 'boolean') return String(v);
  return '…';
}

const TEX_SPECIAL: Record<string, string> = {
  '\\': '\\textbackslash{}', '{': '\\{', '}': '\\}', $: '\\$', '&': '\\&', '#': '\\#',
  '^': '\\textasciicircum{}', _: '\\_', '%': '\\%', '~': '\\textasciitilde{}',
};

/**
 * A report value inside TeX: a number as digits; anything else as escaped `\text{…}`, so a
 * string can never become TeX commands (a report value is data, not markup).
 */
export function texValue(v: unknown): string {
  if (typeof v === 'number') return valueText(v);
  return `\\text{${valueText(v).replace(/[\\{}$&#^_%~]/g, (c) => TEX_SPECIAL[c])}}`;
}

/**
 * The href of a chapter link, or null when it is neither a same-page anchor nor https (a chapter
 * is data: a `javascript:` or `data:` link must not become clickable).
 */
export function safeHref(href: string): string | null {
  if (/^#[A-Za-z0-9_=-]+$/.test(href)) return href;
  try {
    const u = new URL(href);
    return u.protocol === 'https:' && href.startsWith('https://') ? href : null;
  } catch {
    return null;
  }
}

export function renderMarkdown(md: string, opts: RenderOpts): string {
  const tokens: string[] = [];
  const keep = (html: string): string => `\u0002${tokens.push(html) - 1}\u0003`;
  let src = md.replace(/\r\n/g, '\n');

  // 1. fenced code, inline code: opaque
  src = src.replace(/^(```|~~~)([^\n]*)\n([\s\S]*?)^\1[ \t]*$/gm, (_, _f, lang: string, code: string) =>
    keep(`<pre class="code"><code class="lang-${esc(lang.trim())}">${esc(code.replace(/\n$/, ''))}</code></pre>`));
  src = src.replace(/(`+)([^`\n][\s\S]*?)\1/g, (_, _t, code: string) => keep(`<code>${esc(code)}</code>`));
  // 2. math (placeholders inside become plain numbers)
  const math = (tex: string, display: boolean): string => {
    const filled = fillPlaceholders(tex, (p) => texValue(opts.value(p)));
    const key = `${display ? 'D' : 'I'}${filled}`;
    let html = KATEX_CACHE.get(key);
    if (html === undefined) {
      html = katex.renderToString(filled, { displayMode: display, throwOnError: false, output: 'html' });
      if (KATEX_CACHE.size > 4000) KATEX_CACHE.clear();
      KATEX_CACHE.set(key, html);
    }
    return keep(html);
  };
  src = src.replace(/\$\$([\s\S]+?)\$\$/g, (_, tex: string) => math(tex.trim(), true));
  src = src.replace(/(^|[^\\$])\$([^$\n]+?)\$/g, (_, pre: string, tex: string) => pre + math(tex, false));
  src = src.replace(/\\\$/g, '$');
  // 3. embeds and values
  src = src.replace(/\{\{\s*(panel|plot):([A-Za-z0-9_-]+)\s*\}\}/g, (_, kind: string, name: string) =>
    keep(`<div class="doc-embed" data-embed-${kind}="${esc(name)}"></div>`));
  src = src.replace(/\{\{\s*figure:([A-Za-z0-9_-]+)\s*\}\}/g, (whole, name: string) =>
    (isFigure(name) ? keep(`<figure class="course-fig" data-figure="${esc(name)}">${drawFigure(name, (p) => opts.value(p))}</figure>`) : whole));
  src = src.replace(/\{\{\s*([^{}\s]+)\s*\}\}/g, (_, path: string) => {
    const v = opts.value(path);
    return keep(`<span class="num doc-val" data-key="${esc(path)}"${typeof v === 'number' ? ` data-value="${esc(JSON.stringify(v))}" title="${esc(String(v))}"` : ''}>${esc(valueText(v))}</span>`);
  });

  const html = blocks(src.split('\n'));
  return html.replace(/\u0002(\d+)\u0003/g, (_, i: string) => tokens[Number(i)]);
}

function inline(s: string): string {
  let out = esc(s);
  out = out.replace(/\*\*([^*]+)\*\*/g, '<strong>$1</strong>');
  out = out.replace(/(^|[^*\w])\*([^*\s][^*]*?)\*(?!\w)/g, '$1<em>$2</em>');
  out = out.replace(/\[([^\]]+)\]\(([^)\s]+)\)/g, (all: string, text: string, raw: string) => {
    // `out` is escaped already: `raw` holds &amp; etc., checked as the text it stands for.
    const href = safeHref(raw.replace(/&amp;/g, '&').replace(/&quot;/g, '"').replace(/&lt;/g, '<').replace(/&gt;/g, '>'));
    if (href === null) return all;
    const panel = /^#panel=([\w-]+)$/.exec(href);
    if (panel) return `<a href="#panel-${panel[1]}" data-panel-link="${panel[1]}">${text}</a>`;
    if (href.startsWith('#')) return `<a href="${href.replace(/^#/, '#doc-')}" data-doc-link="${href.slice(1)}">${text}</a>`;
    return `<a href="${esc(href)}" rel="noopener" target="_blank">${text}</a>`;
  });
  return out;
}

/** A blockquote's class from its bold opening word: errata, and the course's three boxes. */
const BOX_KINDS: Array<[RegExp, string]> = [
  [/^\*\*(Goals|学习目标)/, ' goals'], [/^\*\*(Summary|小结)/, ' summary'],
  [/^\*\*(Common mistakes|常见错误)/, ' mistakes'], [/\*\*(Erratum|勘误)/, ' erratum'],
];

const EXERCISE_RE = /^:::\s*exercise\s+([A-Za-z0-9_-]+)((?:\s+[^\s]+)*)\s*$/;

/**
 * An exercise (`::: exercise ID [choice A B …] [trace]`, then `::: hint`, `::: solution`, `:::`):
 * the question, an answer field `exercise.ID` (a select for a choice), the hint (shown after a
 * wrong answer) and the worked solution (on request). Checking is wired by course/exercises.ts.
 */
function exerciseHtml(id: string, opts: string[], parts: Record<'q' | 'hint' | 'solution', string[]>): string {
  const choice = opts[0] === 'choice' ? opts.slice(1).filter((o) => o !== 'trace') : null;
  const name = `exercise.${esc(id)}`;
  const label = (c: string) => (has(`c_${c}`) ? t(`c_${c}` as never) : c);
  const field = choice
    ? `<select name="${name}"><option value="">${esc(t('exChoose'))}</option>${choice.map((c) => `<option value="${esc(c)}">${esc(label(c))}</option>`).join('')}</select>`
    : `<input name="${name}" autocomplete="off" spellcheck="false" inputmode="text" size="12">`;
  const trace = opts.includes('trace') ? `<button type="button" class="ex-trace-run" data-ex-trace="">${esc(t('exTrace'))}</button><ol class="ex-trace"></ol>` : '';
  return `<div class="exercise" data-exercise="${esc(id)}" id="ex-${esc(id)}"><div class="ex-q">${blocks(parts.q)}</div>${trace}`
    + `<form class="ex-form" data-keep="ex ${esc(id)} ${esc(t('exCheck'))}" novalidate><label>${esc(t('exAnswer'))} ${field}</label> `
    + `<button type="submit">${esc(t('exCheck'))}</button> <span class="ex-tol"></span></form>`
    + `<p class="ex-feedback" role="status" aria-live="polite"></p>`
    + `<div class="ex-hint" hidden><strong>${esc(t('exHint'))}</strong> ${blocks(parts.hint)}</div>`
    + `<details class="ex-solution"><summary>${esc(t('exSolution'))}</summary>${blocks(parts.solution)}</details></div>`;
}

function blocks(lines: string[]): string {
  const out: string[] = [];
  let i = 0;
  const isBlank = (l: string | undefined) => l === undefined || l.trim() === '';
  while (i < lines.length) {
    const line = lines[i];
    if (isBlank(line)) {
      i++;
      continue;
    }
    const ex = EXERCISE_RE.exec(line);
    if (ex) {
      const parts: Record<'q' | 'hint' | 'solution', string[]> = { q: [], hint: [], solution: [] };
      let cur: keyof typeof parts = 'q';
      for (i++; i < lines.length && !/^:::\s*$/.test(lines[i]); i++) {
        const sub = /^:::\s*(hint|solution)\s*$/.exec(lines[i]);
        if (sub) cur = sub[1] as 'hint' | 'solution';
        else parts[cur].push(lines[i]);
      }
      i++;
      out.push(exerciseHtml(ex[1], ex[2].trim().split(/\s+/).filter(Boolean), parts));
      continue;
    }
    const hm = /^(#{1,6})\s+(.*?)\s*(?:\{#([\w-]+)\})?\s*$/.exec(line);
    if (hm) {
      const id = hm[3] ? ` id="doc-${hm[3]}" data-anchor="${hm[3]}"` : '';
      out.push(`<h${hm[1].length}${id}>${inline(hm[2])}</h${hm[1].length}>`);
      i++;
      continue;
    }
    if (/^\s*(---+|\*\*\*+)\s*$/.test(line)) {
      out.push('<hr>');
      i++;
      continue;
    }
    if (line.startsWith('>')) {
      const inner: string[] = [];
      while (i < lines.length && lines[i].startsWith('>')) inner.push(lines[i++].replace(/^>\s?/, ''));
      const text = inner.join('\n');
      const kind = BOX_KINDS.find(([re]) => re.test(text))?.[1] ?? '';
      out.push(`<blockquote class="doc-note${kind}">${blocks(inner)}</blockquote>`);
      continue;
    }
    if (line.trim().startsWith('|') && /^\s*\|?\s*:?-{3,}/.test(lines[i + 1] ?? '')) {
      const cells = (l: string) => l.trim().replace(/^\||\|$/g, '').split('|').map((c) => c.trim());
      const head = cells(line);
      i += 2;
      const rows: string[][] = [];
      while (i < lines.length && lines[i].trim().startsWith('|')) rows.push(cells(lines[i++]));
      out.push(`<table class="grid doc-table"><thead><tr>${head.map((c) => `<th>${inline(c)}</th>`).join('')}</tr></thead><tbody>${rows
        .map((r) => `<tr>${r.map((c) => `<td>${inline(c)}</td>`).join('')}</tr>`).join('')}</tbody></table>`);
      continue;
    }
    const li = /^(\s*)([-*]|\d+\.)\s+/.exec(line);
    if (li) {
      const ordered = /\d/.test(li[2]);
      const items: string[] = [];
      while (i < lines.length && /^(\s*)([-*]|\d+\.)\s+/.test(lines[i])) {
        let item = lines[i++].replace(/^(\s*)([-*]|\d+\.)\s+/, '');
        while (i < lines.length && !isBlank(lines[i]) && /^\s{2,}\S/.test(lines[i]) && !/^(\s*)([-*]|\d+\.)\s+/.test(lines[i])) item += ` ${lines[i++].trim()}`;
        items.push(`<li>${inline(item)}</li>`);
      }
      out.push(ordered ? `<ol>${items.join('')}</ol>` : `<ul>${items.join('')}</ul>`);
      continue;
    }
    const para: string[] = [];
    while (i < lines.length && !isBlank(lines[i]) && !/^(#{1,6}\s|>|\s*\|)/.test(lines[i]) && !/^(\s*)([-*]|\d+\.)\s+/.test(lines[i])) para.push(lines[i++]);
    if (para.length === 0) para.push(lines[i++]);
    const text = para.join(' ');
    out.push(/^\u0002\d+\u0003$/.test(text.trim()) ? text.trim() : `<p>${inline(text)}</p>`);
  }
  return out.join('\n');
}
