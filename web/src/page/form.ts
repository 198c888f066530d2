// The input form: one field per FieldSpec (name = JSON path), display units, presets, and the
// error message at each field. Edits go into the compute session's input.
import { h } from '../dom';
import { fmtInput, fmtNum, parseNumber } from '../format';
import { ALL_FIELDS, SECTIONS, effectiveInput, fieldLabel, unitSiblings, type FieldSpec } from '../fields';
import { errText, getLang, t } from '../i18n';
import type { ApiErr } from '../protocol';
import { PRESETS, clone, decodeUnits, getPath, setPath, type Input } from '../state';
import { fromSI, toSI, type UnitId } from '../units';
import type { ComputeSession } from './session';
import { UNITS_KEY, load, store } from './storage';
import { checkUnits } from '../state-check';
import { closeInputs } from './drawer';
import { choiceText } from '../vendors';

/** The SI field a raw firmware value was converted from (the error's `source` parameter). */
export function sourceField(e: ApiErr): string | null {
  const source = e.code === 'raw_outside_from' ? e.params?.source : undefined;
  return typeof source === 'string' ? source : null;
}

/** The other field of a conflict (two fields that set the same motor value): marked as well. */
export function otherField(e: ApiErr): string | null {
  const other = e.code === 'both_given' ? e.params?.other : undefined;
  return typeof other === 'string' ? other : null;
}

export class InputForm {
  constructor(private root: HTMLElement, private session: ComputeSession) {
    this.useUnits(location.hash);
  }

  /** The display units to show: a link's (`hash` with &u=) win over the ones this browser chose
   * last; both checked. */
  useUnits(hash: string): void {
    const fromLink = decodeUnits(hash);
    this.session.units = checkUnits(fromLink ? JSON.stringify(fromLink) : load(UNITS_KEY));
  }

  /** The display unit chosen for each field (the session keeps it for links). */
  private get units(): Record<string, UnitId> {
    return this.session.units as Record<string, UnitId>;
  }

  private get host(): HTMLElement | null {
    return this.root.querySelector<HTMLElement>('.inputs');
  }

  private unitOf(f: FieldSpec): UnitId | undefined {
    if (!f.units) return undefined;
    const u = this.units[f.path];
    return u && f.units.includes(u) ? u : f.units[0];
  }

  private fieldEl(f: FieldSpec): HTMLElement {
    const input = this.session.input;
    const v = getPath(input, f.path);
    const enabled = f.enabled ? f.enabled(input) : true;
    const label = h('span', { class: 'lbl' }, fieldLabel(f, getLang()));
    let control: HTMLElement;
    if (f.kind === 'select') {
      control = h('select', { name: f.path, disabled: !enabled, onchange: (ev: Event) => this.onSelect(f, (ev.target as HTMLSelectElement).value) },
        (f.options ?? []).map((o) => h('option', { value: o, selected: String(v ?? f.options?.[0]) === o }, choiceText(f.path, o))));
    } else if (f.kind === 'bool') {
      control = h('input', { type: 'checkbox', name: f.path, checked: v === true, onchange: (ev: Event) => this.onBool(f, (ev.target as HTMLInputElement).checked) });
    } else {
      const unit = this.unitOf(f);
      const shown = typeof v === 'number' ? (unit ? fromSI(v, unit) : v) : null;
      control = h('input', {
        name: f.path, type: 'text', inputmode: 'decimal', autocomplete: 'off', spellcheck: 'false',
        value: fmtInput(shown), disabled: !enabled, 'data-unit': unit ?? f.unit ?? '',
        oninput: (ev: Event) => this.onNumber(f, (ev.target as HTMLInputElement).value),
      });
    }
    const unitEl = f.units
      ? h('select', { class: 'unit', 'data-unit-for': f.path, 'aria-label': t('unit'), disabled: !enabled, onchange: (ev: Event) => this.onUnit(f, (ev.target as HTMLSelectElement).value as UnitId) },
          // "kHz" on a period field is the control frequency f_s = 1/Ts (said in the tooltip: a
          // longer label is cut in the 72 px unit box).
          f.units.map((u) => h('option', { value: u, selected: this.unitOf(f) === u, title: u === 'kHz' ? 'f_s = 1/Ts' : null }, u)))
      : f.unit ? h('span', { class: 'unit' }, f.unit) : null;
    return h('label', { class: `field kind-${f.kind}${enabled ? '' : ' disabled'}` },
      label, h('span', { class: 'ctl' }, control, unitEl), h('span', { class: 'err', 'data-err-for': f.path }));
  }

  /** (Re)build the form from the session's input, keeping which sections are open. */
  render(): void {
    const host = this.host;
    if (!host) return;
    const open = new Set([...host.querySelectorAll<HTMLDetailsElement>('details[open]')].map((d) => d.dataset.section));
    const first = !host.childElementCount;
    host.replaceChildren(
      h('div', { class: 'inputs-head' },
        h('div', { class: 'inputs-title' }, h('h2', {}, t('inputs')),
          h('button', { type: 'button', class: 'inputs-close', onclick: closeInputs }, t('inputsClose'))),
        // The reason the numbers are stale, where the user types (the banner over the panels may be
        // off screen or under the drawer).
        h('div', { class: 'stale-note', role: 'status' }),
        h('label', { class: 'preset' }, h('span', {}, t('preset')),
          h('select', { name: 'preset', onchange: (ev: Event) => this.onPreset((ev.target as HTMLSelectElement).value) },
            h('option', { value: '' }, t('presetCustom')),
            PRESETS.map((p) => h('option', { value: p.id, selected: this.matchesPreset(p.input) }, p.label[getLang()])))),
        h('button', { type: 'button', class: 'from-datasheet', title: t('fromDatasheetTitle'), onclick: () => this.onFromDatasheet() }, t('fromDatasheet')),
        this.blank ? h('p', { class: 'hint blank-start' }, t('fromDatasheetStarted')) : null),
      // The datasheet and raw sections start collapsed, but open when the input uses them.
      ...SECTIONS.map((s) => h('details', { class: 'section', 'data-section': s.id, open: (first ? !s.collapsed : open.has(s.id)) || ((s.id === 'datasheet' || s.id === 'raw') && Object.keys(this.session.input[s.id] ?? {}).length > 0) },
        h('summary', {}, t(s.title), h('span', { class: 'err', 'data-err-for': s.id })),
        s.hint ? h('p', { class: 'hint' }, t(s.hint)) : null,
        h('div', { class: 'fields' }, s.fields.map((f) => this.fieldEl(f))))),
    );
    this.updatePlaceholders();
    this.session.errorsChanged();
  }

  /**
   * The message at each field: the page's own check first, then Python's, then the simulation's.
   * A raw firmware value converted from an SI field ("70000 (from motor.rated_voltage_v) is
   * outside Uint16") is shown at that SI field too, where it was typed; a collapsed section with
   * an error opens.
   */
  showErrors(): void {
    const { localErrors, remoteError, simFieldError, panelFieldErrors, stateNotes } = this.session;
    const at = (e: ApiErr | null, f: string): boolean => !!e && (e.field === f || sourceField(e) === f || otherField(e) === f);
    for (const el of this.root.querySelectorAll<HTMLElement>('.inputs [data-err-for]')) {
      const f = el.dataset.errFor ?? '';
      let msg = localErrors.get(f) ?? '';
      // A conflict's sentence names both fields itself; a raw value's names the field it came from.
      if (!msg && remoteError && at(remoteError, f)) msg = `${remoteError.field === f || otherField(remoteError) ? '' : `${remoteError.field}: `}${errText(remoteError)}`;
      if (!msg && simFieldError?.field === f) msg = errText(simFieldError);
      for (const e of panelFieldErrors.values()) if (!msg && e.field === f) msg = errText(e);
      // A value from the link that could not be used: a note, not an error (the default is used).
      const note = msg ? '' : stateNotes.get(f) ?? '';
      // Written only when it changes: a text node replaced on every keystroke re-laid out each field.
      if (el.textContent !== (msg || note)) el.textContent = msg || note;
      el.closest('.field')?.classList.toggle('invalid', msg !== '');
      el.closest('.field')?.classList.toggle('noted', note !== '');
      const sec = el.closest<HTMLDetailsElement>('details.section');
      if (msg && sec && !sec.open) sec.open = true;
    }
  }

  /** Whether an error on `field` has an element of its own in the form. */
  hasField(field: string): boolean {
    return this.root.querySelector(`.inputs [data-err-for="${CSS.escape(field)}"]`) !== null;
  }

  private matchesPreset(p: Input): boolean {
    return JSON.stringify(effectiveInput(p)) === JSON.stringify(effectiveInput(this.session.input));
  }

  /** Derived and optional fields show the value Python used ("= 1.23") as placeholder. */
  updatePlaceholders(): void {
    // Only from a report of the input in the form: never another motor's values (a blank datasheet
    // start kept the example's "= 220" under fields it had emptied).
    const report = this.session.outdated ? null : this.session.report;
    for (const f of ALL_FIELDS) {
      const el = this.root.querySelector<HTMLInputElement>(`.inputs input[name="${f.path}"]`);
      if (!el || f.kind === 'bool') continue;
      let ph = '';
      if (f.placeholderFrom && report) {
        const v = getPath(report, f.placeholderFrom);
        if (typeof v === 'number') {
          const u = this.unitOf(f);
          ph = `= ${fmtNum(u ? fromSI(v, u) : v, 8)}`;
          const title = `${t('derived')}: ${fmtNum(u ? fromSI(v, u) : v, 12)}`;
          if (el.title !== title) el.title = title;
        }
      } else if (f.optional && report) {
        const v = getPath(report.input, f.path);
        if (typeof v === 'number') ph = `= ${fmtNum(v, 8)}`;
      }
      if (el.placeholder !== ph) el.placeholder = ph;
    }
  }

  private onNumber(f: FieldSpec, text: string): void {
    const s = this.session;
    s.touched(f.path);
    const r = parseNumber(text, f.kind === 'int');
    if (!r.ok) return s.setLocalError(f.path, t(r.error === 'integer' ? 'errInteger' : 'errNumber'));
    const unit = this.unitOf(f);
    const si = r.value === null ? null : unit ? toSI(r.value, unit) : r.value;
    // f_s = 0 kHz has no period: JSON would turn Infinity into null ("is required").
    if (si !== null && !Number.isFinite(si)) return s.setLocalError(f.path, t('errPositive'));
    setPath(s.input as Record<string, unknown>, f.path, si);
    s.clearRemoteError();
    s.setLocalError(f.path, null);
    this.syncPresetSelect();
    s.schedule();
  }

  private onSelect(f: FieldSpec, value: string): void {
    const { input, report } = this.session;
    this.session.touched(f.path);
    // The empty choice ("—") is an absent field (pulab's default, or "not given").
    setPath(input as Record<string, unknown>, f.path, value === '' ? null : value);
    if (f.path === 'current_loop.method' && value === 'manual' && report) {
      // Start manual tuning from the current design.
      const cl = input.current_loop ?? (input.current_loop = {});
      cl.kp ??= report.current_pi.d.kp;
      cl.ki ??= report.current_pi.d.ki;
    }
    if (f.path === 'current_loop.method' && value === 'integers' && report) {
      const cl = input.current_loop ?? (input.current_loop = {});
      cl.pm_kp ??= report.current_pi.d.pm_kp;
      cl.pm_ki ??= report.current_pi.d.pm_ki;
    }
    if (f.path === 'conventions.base' && value === 'custom' && report) {
      const c = input.conventions ?? (input.conventions = {});
      c.base_voltage_v ??= report.base.U_b;
      c.base_current_a ??= report.base.I_b;
    }
    this.session.clearRemoteError();
    this.render();
    this.session.schedule();
  }

  private onBool(f: FieldSpec, v: boolean): void {
    this.session.touched(f.path);
    setPath(this.session.input as Record<string, unknown>, f.path, v);
    this.session.schedule();
  }

  private onUnit(f: FieldSpec, u: UnitId): void {
    for (const g of unitSiblings(f)) this.units[g.path] = u;
    store(UNITS_KEY, JSON.stringify(this.units));
    this.render();
    this.session.schedule(); // the link (#in=…&u=…) carries the units too
  }

  private onPreset(id: string): void {
    const p = PRESETS.find((x) => x.id === id);
    if (!p) return;
    this.blank = false;
    this.session.replaceInput(clone(p.input));
    this.render();
  }

  /** Started from a blank datasheet (until a preset is chosen): says so in the form's head. */
  private blank = false;

  /** A blank form with the datasheet section open: nothing of the example motor is kept. */
  private onFromDatasheet(): void {
    this.blank = true;
    this.session.replaceInput({ datasheet: {} });
    this.render();
    const sec = this.host?.querySelector<HTMLDetailsElement>('details[data-section="datasheet"]');
    if (sec) sec.open = true;
    sec?.querySelector<HTMLElement>('input, select')?.focus();
  }

  private syncPresetSelect(): void {
    const sel = this.root.querySelector<HTMLSelectElement>('select[name="preset"]');
    const id = PRESETS.find((p) => this.matchesPreset(p.input))?.id ?? '';
    if (sel && sel.value !== id) sel.value = id;
  }
}
