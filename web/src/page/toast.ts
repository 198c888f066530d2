// A short message at the bottom of the page (link copied, export failed), with optional content.
import { h } from '../dom';
import { t } from '../i18n';

export function toast(root: HTMLElement, msg: string, extra?: HTMLElement): void {
  const el = root.querySelector('.toast');
  if (!el) return;
  el.replaceChildren(h('span', {}, msg), extra ?? '');
  el.classList.add('show');
  setTimeout(() => el.classList.remove('show'), extra ? 12000 : 2500);
}

/** Copy a link; where the clipboard is refused, show it selected in a box to copy by hand. */
export async function copyLinkToast(root: HTMLElement, url: string): Promise<void> {
  try {
    await navigator.clipboard.writeText(url);
    toast(root, t('linkCopied'));
  } catch {
    const box = h('input', { class: 'linkbox', value: url, readonly: true }) as HTMLInputElement;
    toast(root, t('linkCopyFailed'), box);
    box.select();
  }
}
