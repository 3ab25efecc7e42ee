// ESLint flat config: @eslint/js recommended + typescript-eslint recommended (the syntactic set,
// not the type-checked one, so `npx eslint .` stays fast on two cores). Formatting is Prettier's
// job (`npm run format`), so no stylistic rules here.
import js from '@eslint/js';
import { defineConfig } from 'eslint/config';
import tseslint from 'typescript-eslint';

// The `globals` package is not installed: the few globals our plain JavaScript files use, by hand.
// (TypeScript files need none: typescript-eslint turns `no-undef` off for them, tsc checks names.)
const shared = {
  console: 'readonly',
  setTimeout: 'readonly',
  clearTimeout: 'readonly',
  setInterval: 'readonly',
  clearInterval: 'readonly',
  queueMicrotask: 'readonly',
  structuredClone: 'readonly',
  performance: 'readonly',
  URL: 'readonly',
  URLSearchParams: 'readonly',
  TextEncoder: 'readonly',
  TextDecoder: 'readonly',
  AbortController: 'readonly',
  MessageChannel: 'readonly',
  fetch: 'readonly',
};
const node = {
  ...shared,
  process: 'readonly',
  Buffer: 'readonly',
  global: 'readonly',
  globalThis: 'readonly',
  setImmediate: 'readonly',
  clearImmediate: 'readonly',
};
const commonjs = { require: 'readonly', module: 'writable', exports: 'writable', __dirname: 'readonly', __filename: 'readonly' };
const browser = {
  ...shared,
  window: 'readonly',
  document: 'readonly',
  self: 'readonly',
  navigator: 'readonly',
  location: 'readonly',
  requestAnimationFrame: 'readonly',
  cancelAnimationFrame: 'readonly',
  Worker: 'readonly',
  Blob: 'readonly',
};

export default defineConfig(
  {
    // Built, installed or generated files.
    ignores: [
      '**/dist/**',
      '**/node_modules/**',
      'packs/**',
      'test-artifacts/**',
      'coverage/**',
      '**/.vite/**',
      'examples/dist/**',
      'examples/public/classic/**',
      'examples/public/api/**',
    ],
  },
  js.configs.recommended,
  tseslint.configs.recommended,
  {
    files: ['**/*.{ts,mts,cts,js,mjs,cjs}'],
    // A disable comment that silences nothing is stale (the code changed): an error, not ESLint's warning.
    linterOptions: { reportUnusedDisableDirectives: 'error' },
    rules: {
      // `a[i]!` is deliberate: with noUncheckedIndexedAccess the hot loops index typed arrays whose
      // lengths are checked once up front; a `!` costs nothing at run time, a guard would. (Not in
      // `recommended`, only in `strict`: kept off here so a move to `strict` keeps it allowed.)
      '@typescript-eslint/no-non-null-assertion': 'off',
      // `_name` marks a name kept on purpose: a parameter of a signature, a property left out of a rest.
      '@typescript-eslint/no-unused-vars': [
        'error',
        { argsIgnorePattern: '^_', varsIgnorePattern: '^_', caughtErrorsIgnorePattern: '^_', ignoreRestSiblings: true },
      ],
    },
  },
  {
    // Node scripts, benchmarks, build scripts and test helpers written in plain JavaScript.
    files: ['scripts/**/*.{js,mjs,mts}', 'bench/**/*.{js,mjs}', 'packages/*/classic/*.mjs', 'tests/**/*.{js,mjs}'],
    languageOptions: { globals: node },
  },
  {
    files: ['**/*.cjs'],
    languageOptions: { sourceType: 'commonjs', globals: { ...node, ...commonjs } },
    // A CommonJS file (webpack's config) loads its modules with require(): that is its import.
    rules: { '@typescript-eslint/no-require-imports': 'off' },
  },
  {
    // The consumer apps bundled for the browser by the packaging tests.
    files: ['tests/consumers/apps/**/*.js'],
    languageOptions: { globals: browser },
  },
);
