// ESLint flat config: @eslint/js recommended + typescript-eslint recommended (the syntactic set,
// not the type-checked one, so `npx eslint .` stays fast on two cores). Formatting is Prettier's
// job (`npm run format`), so no stylistic rules here.
import js from '@eslint/js';
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

export default tseslint.config(
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
    linterOptions: { reportUnusedDisableDirectives: 'error' },
    rules: {
      // `a[i]!` is deliberate: with noUncheckedIndexedAccess the hot loops index typed arrays whose
      // lengths are checked once up front; a `!` costs nothing at run time, a guard would.
      '@typescript-eslint/no-non-null-assertion': 'off',
      // `_name` marks a parameter kept for the signature (an interface, a callback's position).
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
  },
  {
    // The consumer apps bundled for the browser by the packaging tests.
    files: ['tests/consumers/apps/**/*.js'],
    languageOptions: { globals: browser },
  },
);
