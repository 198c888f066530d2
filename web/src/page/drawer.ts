// The inputs as a drawer on narrow screens (style.css, max-width 1000px): one tap away from the
// answer, closed by its button, the backdrop or Esc. On wide screens they are a sidebar and these
// calls change nothing visible.
const OPEN = 'inputs-open';

export function openInputs(): void {
  document.body.classList.add(OPEN);
}

export function closeInputs(): void {
  document.body.classList.remove(OPEN);
}

let wired = false;
/** Esc closes the drawer (listening on the document once: the page is rebuilt on a language switch). */
export function wireDrawer(): void {
  if (wired) return;
  wired = true;
  document.addEventListener('keydown', (ev) => {
    if (ev.key === 'Escape' && document.body.classList.contains(OPEN)) closeInputs();
  });
}
