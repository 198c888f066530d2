// localStorage that never throws (private mode, blocked storage, quota): the page works without it.
export const LANG_KEY = 'pulab.lang';
export const UNITS_KEY = 'pulab.units.v1';

export function store(key: string, value: string): void {
  try {
    localStorage.setItem(key, value);
  } catch {
    /* private mode or quota: nothing to keep */
  }
}

export function load(key: string): string | null {
  try {
    return localStorage.getItem(key);
  } catch {
    return null;
  }
}
