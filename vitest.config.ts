import { defineConfig } from 'vitest/config';

export default defineConfig({
  test: {
    include: ['tests/web/**/*.test.ts'],
    environment: 'node',
    testTimeout: 60_000,
    hookTimeout: 120_000,
    // One Pyodide instance per file is enough; keep files in one worker so boots are not repeated.
    pool: 'forks',
    fileParallelism: false,
    isolate: false,
  },
});
