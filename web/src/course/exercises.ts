// The exercises of a rendered chapter (docs/render.ts makes them): an answer is sent to pulab
// (`course` → pulab.api.course_json, which reads the expected value from the report of the
// reader's motor), and the element gets data-exercise-state = correct | wrong. Progress is kept in
// localStorage per motor and can be exported.
import type { PulabClient } from '../rpc';
import type { Tolerance } from '../generated/api-types';
import type { Json } from '../protocol';
import type { Input } from '../state';
import { getLang, t } from '../i18n';
import { fmtNum } from '../format';
import { load, store } from '../page/storage';

export type ExerciseState = 'correct' | 'wrong';

export interface Attempt {
  state: ExerciseState;
  answer: string;
  at: string;
}

/** Stored progress: motor key (its normalized input) → exercise id → the last checked attempt. */
export interface Progress {
  version: 1;
  motors: Record<string, { input: Json; exercises: Record<string, Attempt> }>;
}

export const PROGRESS_KEY = 'pulab-course-progress';

const EMPTY = (): Progress => ({ version: 1, motors: {} });

export function loadProgress(): Progress {
  try {
    const p = JSON.parse(load(PROGRESS_KEY) ?? 'null') as Progress | null;
    if (p && p.version === 1 && typeof p.motors === 'object' && p.motors !== null) return p;
  } catch {
    // an unreadable entry: start again
  }
  return EMPTY();
}

const saveProgress = (p: Progress): void => store(PROGRESS_KEY, JSON.stringify(p));

export const clearProgress = (): void => saveProgress(EMPTY());

/** The key of a motor: its input as pulab normalized it (the report's `input`). */
export const motorKey = (input: unknown): string => JSON.stringify(input ?? null);

export interface ExerciseEnv {
  /** The input pulab computes the expected answers from (the reader's motor). */
  input(): Input;
  /** The normalized input of the shown report (the progress key), or null before the first report. */
  reportInput(): unknown;
  /** Raw firmware inputs of the shown report (the tracer's variables), if any. */
  raw(): Record<string, number> | null;
  client(): PulabClient | null;
  /** Called after an answer was checked (the course page updates its progress count). */
  changed?(): void;
}

const shown = (v: unknown): string => (typeof v === 'number' ? fmtNum(v, 6) : String(v));

/** Show an attempt on its exercise element (also after a re-render, from the stored progress). */
function show(el: HTMLElement, a: Attempt, expected?: unknown, tol?: Tolerance): void {
  el.dataset.exerciseState = a.state;
  const fb = el.querySelector<HTMLElement>(':scope > .ex-feedback');
  const tolText = tol ? tol[getLang()] : '';
  if (fb) {
    fb.textContent = a.state === 'correct'
      ? (expected === undefined ? '✓' : `✓ ${t('exCorrect', { expected: shown(expected), tol: tolText })}`)
      : `✗ ${t('exWrong', { tol: tolText })}`;
    fb.className = `ex-feedback ${a.state}`;
  }
  el.querySelector<HTMLElement>(':scope > .ex-hint')?.toggleAttribute('hidden', a.state !== 'wrong');
}

function fieldError(el: HTMLElement, message: string | null): void {
  const f = el.querySelector<HTMLInputElement | HTMLSelectElement>('[name^="exercise."]');
  f?.setAttribute('aria-invalid', message ? 'true' : 'false');
  const fb = el.querySelector<HTMLElement>(':scope > .ex-feedback');
  if (fb && message) {
    fb.textContent = message;
    fb.className = 'ex-feedback error';
  }
}

/** Restore the stored attempts of the shown motor on every exercise below `root`. */
export function applyProgress(root: HTMLElement, env: ExerciseEnv): void {
  const ri = env.reportInput();
  const saved = ri === null ? undefined : loadProgress().motors[motorKey(ri)]?.exercises;
  for (const el of root.querySelectorAll<HTMLElement>('[data-exercise]')) {
    const a = saved?.[el.dataset.exercise ?? ''];
    if (a) {
      show(el, a);
      const f = el.querySelector<HTMLInputElement | HTMLSelectElement>('[name^="exercise."]');
      if (f && f.value === '') f.value = a.answer;
    }
  }
}

async function checkOne(el: HTMLElement, env: ExerciseEnv): Promise<void> {
  const id = el.dataset.exercise ?? '';
  const field = el.querySelector<HTMLInputElement | HTMLSelectElement>('[name^="exercise."]');
  const client = env.client();
  if (!field) return;
  if (!client) return fieldError(el, t('exNoPython'));
  el.setAttribute('aria-busy', 'true');
  const answer = field.value;
  try {
    const { result } = await client.call('course.check', { input: env.input(), id, answer }, `exercise-${id}`);
    if (!result.ok) return fieldError(el, getLang() === 'zh' ? (result.message_zh ?? result.message) : result.message);
    fieldError(el, null);
    const r = result.result;
    const a: Attempt = { state: r.state, answer, at: new Date().toISOString() };
    show(el, a, r.expected, r.tolerance);
    const ri = env.reportInput();
    if (ri !== null) {
      const p = loadProgress();
      const m = (p.motors[motorKey(ri)] ??= { input: env.input() as Json, exercises: {} });
      m.exercises[id] = a;
      saveProgress(p);
    }
    env.changed?.();
  } catch (e) {
    fieldError(el, e instanceof Error ? e.message : String(e));
  } finally {
    el.removeAttribute('aria-busy');
  }
}

/** Run the exercise's C routine in pulab's tracer with the motor's raw inputs; list each statement. */
async function runTrace(el: HTMLElement, env: ExerciseEnv): Promise<void> {
  const code = el.querySelector('.ex-q pre code')?.textContent ?? '';
  const out = el.querySelector<HTMLElement>('.ex-trace');
  const client = env.client();
  if (!out) return;
  if (!client) {
    out.textContent = t('exNoPython');
    return;
  }
  const raw = env.raw() ?? {};
  const set = Object.fromEntries(Object.entries(raw).filter(([k]) => new RegExp(`\\b${k}\\b`).test(code)));
  const { result } = await client.call('trace', { code, target: 'c28x', set }, 'exercise-trace');
  if (!result.ok) {
    out.textContent = result.message;
    return;
  }
  const steps = result.steps.filter((s) => !s.input);
  out.replaceChildren(...steps.map((s) => {
    const li = document.createElement('li');
    li.textContent = `${t('exTraceLine', { line: s.line, var: s.var ?? s.code, value: s.value ?? '' })}${s.flags.length ? `  ⚠ ${s.flags.join(', ')}` : ''}`;
    if (s.flags.some((f) => f !== 'truncation')) li.className = 'flagged';
    return li;
  }));
}

const envs = new WeakMap<HTMLElement, ExerciseEnv>();

/**
 * Answer checking and the tracer button for every exercise below `root`: listeners are added
 * once per root; each call replaces the environment they use (the report of the latest render).
 */
export function wireExercises(root: HTMLElement, env: ExerciseEnv): void {
  const first = !envs.has(root);
  envs.set(root, env);
  if (!first) return;
  root.addEventListener('submit', (ev) => {
    const form = ev.target as HTMLElement;
    const el = form.closest<HTMLElement>('[data-exercise]');
    if (!el || !form.classList.contains('ex-form')) return;
    ev.preventDefault();
    void checkOne(el, envs.get(root)!);
  });
  root.addEventListener('click', (ev) => {
    const b = (ev.target as HTMLElement).closest<HTMLElement>('[data-ex-trace]');
    const el = b?.closest<HTMLElement>('[data-exercise]');
    if (el) void runTrace(el, envs.get(root)!);
  });
}

/** The progress as a file a trainee hands to the trainer. */
export function exportProgress(): Blob {
  return new Blob([JSON.stringify(loadProgress(), null, 2)], { type: 'application/json' });
}
