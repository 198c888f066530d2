// The page header: title, status slot, share link, exports (report JSON, C header, CSV) and the
// language switch (also used by the embed bar).
import { h } from '../dom';
import { effectiveInput } from '../fields';
import { errText, getLang, t, type Lang } from '../i18n';
import { encodeHash, reportInput, simInput } from '../state';
import type { ComputeSession } from './session';
import { copyLinkToast, toast } from './toast';
import type { Reply } from '../protocol';

export function langSwitch(onSwitch: (l: Lang) => void): HTMLElement {
  return h('div', { class: 'lang', role: 'group' },
    (['zh', 'en'] as Lang[]).map((l) => h('button', { type: 'button', 'data-lang': l, class: getLang() === l ? 'on' : '', onclick: () => onSwitch(l) }, l === 'zh' ? '中文' : 'English')));
}

function download(name: string, text: string, type: string): void {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const a = h('a', { href: url, download: name }) as HTMLAnchorElement;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 5000);
}

type PyExport = 'header' | 'csv_current' | 'csv_pll';

/** Files made by Python (the export.* kinds of pulab.api.call_json): the C header from the report worker, CSVs from the simulation worker. */
async function exportPy(root: HTMLElement, session: ComputeSession, kind: PyExport): Promise<void> {
  if (!session.client?.ready) return;
  const eff = effectiveInput(session.input);
  const c = kind === 'header' ? session.client : session.simWorker() ?? session.client;
  let result: Reply['export.header'];
  try {
    ({ result } = await c.call(`export.${kind}`, { input: kind === 'header' ? reportInput(eff) : simInput(eff) }));
  } catch (e) {
    // The worker died or a newer call replaced this one: say so, never an unhandled rejection.
    return toast(root, t('exportFailed', { m: e instanceof Error ? e.message : String(e) }));
  }
  if (result.ok) {
    const name = kind === 'header' ? 'pulab_params.h' : `pulab_${kind.slice(4)}.csv`;
    download(name, result.text, kind === 'header' ? 'text/x-c' : 'text/csv');
  } else toast(root, `${result.field}: ${errText(result)}`);
}

/**
 * The report JSON as the page shows it: with the simulation (its metrics, traces and PLL review
 * findings) when the simulation report is for the same input as the numbers shown.
 */
export function exportReport(session: Pick<ComputeSession, 'report' | 'simReport'>): string | null {
  const { report, simReport } = session;
  if (!report) return null;
  // The simulation request also asks for the loop analysis, whose options its input echoes.
  const { analysis: _, ...simIn } = (simReport?.input ?? {}) as Record<string, unknown>;
  const same = simReport && JSON.stringify(simIn) === JSON.stringify(report.input);
  return JSON.stringify(same ? simReport : report, null, 2);
}

/** Copy the share link (#in=…); where the clipboard is refused, show it selected in a box. */
async function copyLink(root: HTMLElement, session: ComputeSession): Promise<void> {
  const url = location.href.split('#')[0] + encodeHash(effectiveInput(session.input), session.units);
  await copyLinkToast(root, url);
  document.documentElement.dataset.shareLink = url;
}

/** Menus (`details.menu-host`) close as menus do: an item chosen, a click outside, Esc. Listening
 * on the document once: the header is rebuilt on a language switch. */
let menusWired = false;
function wireMenus(): void {
  if (menusWired) return;
  menusWired = true;
  const openMenus = () => [...document.querySelectorAll<HTMLDetailsElement>('details.menu-host[open]')];
  document.addEventListener('click', (ev) => {
    const target = ev.target as Element;
    for (const d of openMenus()) {
      if (!d.contains(target) || target.closest('.menu button')) d.open = false;
    }
  });
  document.addEventListener('keydown', (ev) => {
    if (ev.key !== 'Escape') return;
    for (const d of openMenus()) {
      d.open = false;
      d.querySelector<HTMLElement>('summary')?.focus();
    }
  });
}

export function renderHeader(root: HTMLElement, session: ComputeSession, lang: HTMLElement): HTMLElement {
  const exportButton = (kind: PyExport, label: Parameters<typeof t>[0]) =>
    h('button', { type: 'button', 'data-export': kind, onclick: () => void exportPy(root, session, kind) }, t(label));
  wireMenus();
  return h('header', { class: 'top' },
    h('div', { class: 'brand' }, h('strong', {}, 'pu-lab'), h('span', { class: 'sub' }, t('subtitle'))),
    // The course is its own page (course.html), with the reader's motor.
    h('a', { class: 'course-link', href: './course.html', 'data-course-link': '', onclick: (ev: Event) => {
      (ev.currentTarget as HTMLAnchorElement).href = `./course.html?lang=${getLang()}${encodeHash(effectiveInput(session.input))}`;
    } }, t('goCourse')),
    h('div', { class: 'status' }),
    h('div', { class: 'actions' },
      h('button', { type: 'button', class: 'copy-link', onclick: () => void copyLink(root, session) }, t('copyLink')),
      h('details', { class: 'export menu-host' }, h('summary', {}, t('export')),
        h('div', { class: 'menu' },
          h('button', { type: 'button', 'data-export': 'json', onclick: () => { const j = exportReport(session); if (j) download('pulab_report.json', j, 'application/json'); } }, t('exportJson')),
          exportButton('header', 'exportHeader'),
          exportButton('csv_current', 'exportCsvCurrent'),
          exportButton('csv_pll', 'exportCsvPll'))),
      lang));
}
