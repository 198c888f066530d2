/** One feature's labels: English, and Chinese with exactly the same keys (the compiler checks). */
export interface Dict<K extends string> {
  en: Record<K, string>;
  zh: Record<K, string>;
}

export function dict<const E extends Record<string, string>>(
  en: E,
  zh: Record<keyof E & string, string>,
): Dict<keyof E & string> {
  return { en, zh };
}
