/**
 * What a browser test counts as a broken page: every console error, page error, failed request
 * and HTTP error status, collected from the moment the page is made.
 */
import type { Page } from 'playwright-core';

/** Starts collecting `page`'s problems into the returned list (call before `page.goto`). */
export function collectProblems(page: Page): string[] {
  const problems: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'error') problems.push(`console.error: ${m.text()}`);
  });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()} ${r.failure()?.errorText ?? ''}`));
  page.on('response', (r) => {
    if (r.status() >= 400) problems.push(`HTTP ${r.status()}: ${r.url()}`);
  });
  return problems;
}
