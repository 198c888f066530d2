// py/pulab bundled as text (the worker and the vitest suite both take it from here).
export const PULAB_FILES = import.meta.glob('../../py/pulab/**/*.py', {
  query: '?raw',
  import: 'default',
  eager: true,
}) as Record<string, string>;
