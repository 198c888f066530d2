// A short message at the bottom of the page (link copied, export failed), with optional content.
import { h } from '../dom';

export function toast(root: HTMLElement, msg: string, extra?: HTMLElement): void {
  const el = root.querySelector('.toast');
  if (!el) return;
  el.replaceChildren(h('span', {}, msg), extra ?? '');
  el.classList.add('show');
  setTimeout(() => el.classList.remove('show'), extra ? 12000 : 2500);
}
