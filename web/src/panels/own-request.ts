// A panel that asks pulab for a report of its own (a section that costs more than the page's
// report, or needs defaults the form leaves out): asked only while the panel is (nearly) on
// screen, the latest answer kept, an input error shown at the form's field and the earlier
// numbers cleared beside it.
import { errText } from '../i18n';
import type { ApiErr } from '../protocol';
import type { Input } from '../state';
import type { Report } from '../generated/report-types';
import type { PanelContext, PanelId } from './panel';

export class OwnRequest<T> {
  key = '';
  data: T | null = null;
  error: string | null = null;
  /** pulab's refusal of the last request (its field, code and both languages' texts). */
  failed: ApiErr | null = null;
  pending = false;
  /** Asked only while on screen: the other panels' reports must not wait behind this one on
   * every keystroke. */
  shown = typeof IntersectionObserver === 'undefined';
  private ctx: PanelContext | null = null;

  constructor(
    private readonly el: HTMLElement,
    private readonly id: PanelId,
    private readonly request: (inp: Input) => Input,
    private readonly pick: (r: Report) => T | null,
    private readonly rerender: (el: HTMLElement, ctx: PanelContext) => void,
  ) {
    if (this.shown) return;
    new IntersectionObserver((entries) => {
      this.shown = entries.some((e) => e.isIntersecting);
      if (this.shown && this.ctx) this.ask(this.ctx);
    }, { rootMargin: '300px' }).observe(el);
  }

  ask(ctx: PanelContext): void {
    this.ctx = ctx;
    if (!ctx.client || !this.shown) return;
    const req = this.request(ctx.input);
    const key = JSON.stringify(req);
    if (key === this.key) return;
    this.key = key;
    this.pending = true;
    void ctx.client.call('report', req, this.id).then(({ result }) => {
      if (key !== this.key) return;
      this.pending = false;
      if (result.ok) {
        this.data = this.pick(result.report);
        this.error = null;
        this.failed = null;
        ctx.fieldError?.(this.id, null);
      } else {
        this.data = null;
        this.failed = result;
        this.error = `${result.field}: ${errText(result)}`;
        ctx.fieldError?.(this.id, result);
      }
      this.rerender(this.el, ctx);
    }, () => undefined);
  }
}
