import { defineConfig } from 'vitest/config';

// Benchmarks are not tests: `npm run bench` runs this config only, never `npm test`.
export default defineConfig({
  test: {
    include: ['tests/bench/**/*.bench.ts'],
    environment: 'node',
    testTimeout: 300_000,
    hookTimeout: 120_000,
  },
});
