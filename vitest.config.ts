import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vitest/config';

const src = (p: string) => fileURLToPath(new URL(p, import.meta.url));

// Unit tests run against the TypeScript sources (fast feedback, exact stack traces);
// tests/node-import.test.ts checks the built packages through their `exports` as a user would.
export default defineConfig({
  resolve: {
    // Exact matches: '@physin/engine' must not swallow '@physin/engine/internal'.
    alias: [
      { find: /^@physin\/algebra$/, replacement: src('./packages/algebra/src/index.ts') },
      { find: /^@physin\/engine$/, replacement: src('./packages/engine/src/index.ts') },
      { find: /^@physin\/engine\/internal$/, replacement: src('./packages/engine/src/internal.ts') },
      { find: /^@physin\/engine\/3d$/, replacement: src('./packages/engine/src/3d.ts') },
    ],
  },
  test: {
    include: ['tests/**/*.test.ts', 'packages/*/test/**/*.test.ts'],
    reporters: ['default', './tests/support/summary-reporter.ts'],
    testTimeout: 120_000,
    hookTimeout: 120_000,
  },
});
