// Registers the offline cache (web/offline/sw.js, built as dist/sw.js) once the page works, so its
// download never competes with the first boot. Production builds only; failure is harmless (the
// page simply does not work offline), so it is reported nowhere but the console.
export function registerOffline(): void {
  if (!import.meta.env.PROD || !('serviceWorker' in navigator)) return;
  navigator.serviceWorker
    .register(new URL('sw.js', document.baseURI), { updateViaCache: 'none' })
    .catch((e: unknown) => console.warn('offline cache not available:', e));
}
