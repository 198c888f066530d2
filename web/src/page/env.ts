// The page's SessionEnv: what the compute session publishes goes to <html data-*>, the address bar
// and localStorage of this document.
import { STORAGE_KEY } from '../state';
import { mark } from './marks';
import { keepReport, knownReport, showSource } from './numbers';
import type { SessionEnv } from './session';
import { store } from './storage';

export function pageEnv(): SessionEnv {
  return {
    attrs: document.documentElement.dataset,
    showSource,
    mark: (step) => mark(step),
    known: knownReport,
    keep: keepReport,
    hash: () => location.hash,
    replaceHash: (hash) => history.replaceState(null, '', hash),
    storeInput: (json) => store(STORAGE_KEY, json),
    onOnline: (retry) => window.addEventListener('online', retry),
  };
}
