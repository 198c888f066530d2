// The course page (course.html): the day-one learning path over the explainer chapters, with the
// reader's motor (#in=, as on the calculator; a trainer's link carries a trainee's motor), the
// exercises checked by pulab, progress export, print/PDF layouts and the trainer's page.
//   course.html[?chapter=ID][&lang=zh|en]#in=…        one chapter of the path
//   course.html?print=course|key[&lang=…]#in=…       every day-one chapter (course), or the answer key
//   course.html?trainer[&first=N&count=K]             trainee links and their answer sheet
import 'katex/dist/katex.min.css';
import '../style.css';
import './course.css';
import { h, table } from '../dom';
import { fmtNum } from '../format';
import { defaultLang, getLang, has, setLang, t, type Lang } from '../i18n';
import { renderMarkdown } from '../docs/render';
import { SEED_INPUT, decodeHash, encodeHash, getPath, reportInput, type Input } from '../state';
import { langSwitch } from '../page/header';
import { LANG_KEY, load, store } from '../page/storage';
import type { PulabClient } from '../rpc';
import type { Json } from '../protocol';
import type { Report } from '../generated/report-types';
import { registerOffline } from '../offline';
import { applyProgress, clearProgress, exportProgress, loadProgress, motorKey, wireExercises } from './exercises';

const CHAPTERS = import.meta.glob('../../../docs/{zh,en}/*.md', { query: '?raw', import: 'default', eager: true }) as Record<string, string>;
const INDEX = Object.values(import.meta.glob('../../../docs/index.json', { import: 'default', eager: true }))[0] as {
  chapters: { id: string; file: string; title: { zh: string; en: string } }[];
};
const COURSE = Object.values(import.meta.glob('../../../docs/course.json', { import: 'default', eager: true }))[0] as {
  day_one: { id: string; title: { zh: string; en: string }; chapters: string[] }[];
  reference: string[];
};

type Answers = Record<string, { chapter: string; expected: Json; unit: string; tolerance: { en: string; zh: string } }>;

const DAY_ONE = COURSE.day_one.flatMap((s) => s.chapters);
const title = (id: string): string => INDEX.chapters.find((c) => c.id === id)?.title[getLang()] ?? id;

function chapterText(id: string): string {
  const file = INDEX.chapters.find((c) => c.id === id)?.file;
  const key = file && (Object.keys(CHAPTERS).find((k) => k.endsWith(`/docs/${getLang()}/${file}`))
    ?? Object.keys(CHAPTERS).find((k) => k.endsWith(`/docs/en/${file}`)));
  return key ? CHAPTERS[key] : '';
}

/** A chapter with the reader's numbers; a panel or plot embed becomes a link to it on the calculator. */
function renderChapter(id: string, report: Report | null, hash: string): HTMLElement {
  const art = h('article', { class: 'doc course-chapter', 'data-chapter': id });
  art.innerHTML = renderMarkdown(chapterText(id), { value: (p) => getPath(report, p) });
  for (const el of art.querySelectorAll<HTMLElement>('[data-embed-panel], [data-embed-plot]')) {
    const name = el.dataset.embedPanel ?? el.dataset.embedPlot ?? '';
    const key = `p_${name}`;
    el.replaceChildren(h('a', { class: 'doc-embed-link', href: `./${hash}`, target: '_blank', rel: 'noopener' },
      `↗ ${has(key) ? t(key as never) : name}`));
  }
  // Panel links (#panel-NAME) and chapter links (#doc-ANCHOR) lead to the calculator.
  for (const a of art.querySelectorAll<HTMLAnchorElement>('a[data-panel-link]')) a.href = `./${hash}`;
  for (const a of art.querySelectorAll<HTMLAnchorElement>('a[data-doc-link]')) a.href = `./${hash}`;
  return art;
}

export class CoursePage {
  private report: Report | null = null;
  private error: string | null = null;
  private answers: Answers | null = null;
  private readonly params = new URLSearchParams(location.search);
  private input: Input;
  private chapter: string;

  constructor(private root: HTMLElement, private client: PulabClient) {
    const lp = this.params.get('lang');
    setLang(lp === 'zh' || lp === 'en' ? lp : defaultLang(navigator.languages, load(LANG_KEY)));
    this.input = reportInput(decodeHash(location.hash) ?? SEED_INPUT);
    const ch = this.params.get('chapter') ?? '';
    this.chapter = INDEX.chapters.some((c) => c.id === ch) ? ch : DAY_ONE[0];
    document.documentElement.dataset.coursePage = this.params.has('trainer') ? 'trainer' : this.params.get('print') ?? 'chapter';
  }

  private get hash(): string {
    return encodeHash(this.input);
  }

  async start(): Promise<void> {
    this.render();
    if (this.params.has('trainer')) return;
    await this.whenReady();
    registerOffline(); // the course works offline like the calculator (sw.js caches every built file)
    try {
      const { result } = await this.client.call('report', this.input, 'report');
      if (result.ok) this.report = result.report;
      else this.error = `${result.field}: ${getLang() === 'zh' ? result.message_zh ?? result.message : result.message}`;
      if (this.params.get('print') === 'key') {
        const a = await this.client.call('course.answers', { input: this.input });
        if (a.result.ok) this.answers = a.result.answers;
      }
    } catch (e) {
      this.error = e instanceof Error ? e.message : String(e);
    }
    this.render();
    document.documentElement.dataset.courseReady = this.error ? 'error' : 'ready';
  }

  private whenReady(): Promise<void> {
    if (this.client.ready) return Promise.resolve();
    return new Promise((resolve) => {
      const prev = this.client.events.onReady;
      this.client.events.onReady = (ms, v) => {
        prev?.(ms, v);
        resolve();
      };
    });
  }

  private switchLang(l: Lang): void {
    setLang(l);
    store(LANG_KEY, l);
    const u = new URL(location.href);
    u.searchParams.set('lang', l);
    history.replaceState(null, '', u);
    this.render();
  }

  private open(id: string): void {
    this.chapter = id;
    const u = new URL(location.href);
    u.searchParams.set('chapter', id);
    history.pushState(null, '', u);
    this.render();
    window.scrollTo(0, 0);
  }

  private env() {
    return {
      input: () => this.input,
      reportInput: () => this.report?.input ?? null,
      raw: () => this.report?.vendor?.raw ?? null,
      client: () => (this.client.ready ? this.client : null),
      changed: () => this.renderProgress(),
    };
  }

  private progressText(): string {
    const saved = this.report ? loadProgress().motors[motorKey(this.report.input)]?.exercises ?? {} : {};
    const total = DAY_ONE.reduce((n, id) => n + (chapterText(id).match(/^:::\s*exercise\s/gm)?.length ?? 0), 0);
    const done = Object.values(saved).filter((a) => a.state === 'correct').length;
    return t('courseProgress', { done, total });
  }

  private renderProgress(): void {
    const el = this.root.querySelector('.course-progress');
    if (el) el.textContent = this.progressText();
  }

  private header(): HTMLElement {
    const trainee = this.params.get('trainee');
    const m = (this.input.motor ?? {}) as Record<string, Json>;
    const motor = `${m.rated_voltage_v ?? '?'} V · ${m.rated_current_a ?? '?'} A · ${m.rated_freq_hz ?? '?'} Hz`;
    const exportBtn = h('button', { type: 'button', 'data-course-export': '', onclick: () => {
      const url = URL.createObjectURL(exportProgress());
      const a = h('a', { href: url, download: 'pulab-course-progress.json' }) as HTMLAnchorElement;
      document.body.append(a);
      a.click();
      a.remove();
      setTimeout(() => URL.revokeObjectURL(url), 5000);
    } }, t('courseExport'));
    const reset = h('button', { type: 'button', onclick: () => { clearProgress(); this.render(); } }, t('courseReset'));
    // The trainer's page is about many motors: no reader's motor or progress there.
    const trainer = this.params.has('trainer');
    return h('header', { class: 'top course-top' },
      h('div', { class: 'brand' }, h('strong', {}, 'pu-lab'), h('span', { class: 'sub' }, t('courseTitle'))),
      trainer ? null : h('div', { class: 'course-motor' }, `${t('courseMotor')}${trainee ? ` (${t('courseTrainee', { n: trainee })})` : ''}: ${motor}`),
      h('div', { class: 'actions' },
        h('a', { href: `./${this.hash}`, class: 'course-site' }, t('courseSite')),
        trainer ? null : [h('span', { class: 'course-progress' }, this.progressText()), exportBtn, reset],
        trainer
          ? h('a', { href: `./course.html?lang=${getLang()}`, class: 'course-trainer-link' }, t('goCourse'))
          : h('a', { href: `./course.html?trainer&lang=${getLang()}`, class: 'course-trainer-link' }, t('courseTrainer')),
        h('button', { type: 'button', onclick: () => window.print() }, t('coursePrint')),
        langSwitch((l) => this.switchLang(l))));
  }

  private nav(): HTMLElement {
    const link = (id: string) => h('li', {}, h('a', {
      href: `?chapter=${id}&lang=${getLang()}${this.hash}`, class: id === this.chapter ? 'on' : '', 'data-course-chapter': id,
      onclick: (ev: Event) => { ev.preventDefault(); this.open(id); },
    }, title(id)));
    return h('nav', { class: 'course-nav' },
      h('h2', {}, t('courseDayOne')),
      h('ol', { class: 'course-steps' }, COURSE.day_one.map((s, i) => h('li', {},
        h('span', { class: 'course-step' }, `${t('courseStep', { n: i + 1 })}: ${s.title[getLang()]}`),
        h('ul', {}, s.chapters.map(link))))),
      h('h2', {}, t('courseReference')),
      h('ul', { class: 'course-ref' }, COURSE.reference.map(link)));
  }

  private status(): HTMLElement | null {
    if (this.error) return h('p', { class: 'error course-error', role: 'alert' }, t('courseFailed', { msg: this.error }));
    if (!this.report) return h('p', { class: 'note course-loading' }, t('courseLoading'));
    return null;
  }

  render(): void {
    document.documentElement.lang = getLang() === 'zh' ? 'zh-CN' : 'en';
    document.title = `pu-lab — ${t('courseTitle')}`;
    if (this.params.has('trainer')) return void this.root.replaceChildren(this.header(), new TrainerView(this.client).el);
    const print = this.params.get('print');
    const main = h('main', { class: 'course-main' });
    const st = this.status();
    if (st) main.append(st);
    if (print === 'course' || print === 'key') {
      document.documentElement.dataset.print = print;
      for (const id of DAY_ONE) {
        const art = renderChapter(id, this.report, this.hash);
        // The key keeps each chapter's title and exercises (questions and worked solutions) only.
        if (print === 'key') for (const c of [...art.children]) if (!c.matches('h1, [data-exercise]')) c.remove();
        main.append(art);
      }
      if (print === 'key') {
        main.prepend(this.answerTable());
        for (const d of main.querySelectorAll('details.ex-solution')) d.setAttribute('open', '');
      }
      this.root.replaceChildren(this.header(), main);
    } else {
      main.append(renderChapter(this.chapter, this.report, this.hash));
      const i = DAY_ONE.indexOf(this.chapter);
      const next = DAY_ONE[i + 1];
      if (next) main.append(h('p', { class: 'course-next' }, h('a', { href: `?chapter=${next}`, onclick: (ev: Event) => { ev.preventDefault(); this.open(next); } }, `→ ${title(next)}`)));
      this.root.replaceChildren(this.header(), h('div', { class: 'course-body' }, this.nav(), main));
    }
    wireExercises(main, this.env());
    applyProgress(main, this.env());
  }

  private answerTable(): HTMLElement {
    const rows = Object.entries(this.answers ?? {}).map(([id, a]) => [
      title(a.chapter), h('a', { href: `#ex-${id}` }, id),
      typeof a.expected === 'number' ? `${fmtNum(a.expected, 6)} ${a.unit}` : has(`c_${String(a.expected)}`) ? t(`c_${String(a.expected)}` as never) : String(a.expected),
      a.tolerance[getLang()]]);
    return h('section', { class: 'course-key' }, h('h1', {}, t('answerKey')),
      table([t('trainerChapter'), t('trainerExercise'), t('courseAnswer'), t('trainerTol')], rows, 'course-key-table'));
  }
}

/** The trainer's page: trainee numbers → links with each trainee's motor, and the answer sheet. */
class TrainerView {
  readonly el = h('main', { class: 'course-main trainer' });

  constructor(private client: PulabClient) {
    const p = new URLSearchParams(location.search);
    const first = h('input', { name: 'trainer.first', value: p.get('first') ?? '1', inputmode: 'numeric', size: '5' }) as HTMLInputElement;
    const count = h('input', { name: 'trainer.count', value: p.get('count') ?? '8', inputmode: 'numeric', size: '5' }) as HTMLInputElement;
    const out = h('div', { class: 'trainer-out' });
    const make = async (): Promise<void> => {
      const { result } = await this.client.call('course.trainees', { start: first.value, count: count.value });
      if (!result.ok) {
        out.replaceChildren(h('p', { class: 'error', role: 'alert' }, `${result.field}: ${getLang() === 'zh' ? result.message_zh ?? result.message : result.message}`));
        return;
      }
      const trainees = result.trainees;
      const sheets = await Promise.all(trainees.map(async (tr) => {
        const a = await this.client.call('course.answers', { input: tr.input });
        return a.result.ok ? a.result.answers : null;
      }));
      const base = new URL('./course.html', location.href).href;
      const links = trainees.map((tr) => {
        const m = tr.input.motor as Record<string, Json>;
        const url = `${base}?trainee=${tr.n}&lang=${getLang()}${encodeHash(tr.input)}`;
        return [String(tr.n), `${m.rated_voltage_v} V · ${m.rated_current_a} A · ${m.rated_freq_hz} Hz`, h('a', { href: url, 'data-trainee-link': String(tr.n) }, url)];
      });
      const ids = Object.keys(sheets[0] ?? {});
      const sheetRows = ids.map((id) => [id, ...sheets.map((s) => {
        const v = s?.[id]?.expected;
        return typeof v === 'number' ? fmtNum(v, 5) : has(`c_${String(v)}`) ? t(`c_${String(v)}` as never) : String(v ?? '—');
      })]);
      out.replaceChildren(
        table(['#', t('courseMotor'), t('trainerLink')], links, 'trainer-links'),
        h('h2', {}, t('trainerSheet')),
        table([t('trainerExercise'), ...trainees.map((tr) => String(tr.n))], sheetRows, 'trainer-sheet'));
      document.documentElement.dataset.trainerReady = String(trainees.length);
    };
    this.el.append(h('h1', {}, t('trainerTitle')),
      h('form', { class: 'trainer-form', onsubmit: (ev: Event) => { ev.preventDefault(); void make(); } },
        h('label', {}, `${t('trainerFirst')} `, first), ' ', h('label', {}, `${t('trainerCount')} `, count), ' ',
        h('button', { type: 'submit' }, t('trainerMake'))),
      out);
    if (client.ready) void make();
    else {
      const prev = client.events.onReady;
      client.events.onReady = (ms, v) => {
        prev?.(ms, v);
        void make();
      };
    }
  }
}
