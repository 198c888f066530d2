// Registers the offline cache (web/offline/sw.js, built as dist/sw.js) once the page works, so its
// download never competes with the first boot (nor with the other panels of a docs page, which go
// live one after another: hence the pause after the first answer). Production builds only; failure is harmless (the
// page simply does not work offline), so it is reported nowhere but the console.
export function registerOffline(): void {
  if (!import.meta.env.PROD || !('serviceWorker' in navigator)) return;
  navigator.serviceWorker
    .register(new URL('sw.js', document.baseURI), { updateViaCache: 'none' })
    .catch((e: unknown) => console.warn('offline cache not available:', e));
}

/** `registerOffline` after `pauseMs` and then when the page is idle (within 2 s more). */
export function registerOfflineLater(pauseMs = 5000): void {
  setTimeout(() => {
    if (typeof requestIdleCallback === 'function') requestIdleCallback(registerOffline, { timeout: 2000 });
    else registerOffline();
  }, pauseMs);
}
