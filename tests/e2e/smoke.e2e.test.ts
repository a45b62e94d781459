import { afterAll, beforeAll, expect, inject, test } from 'vitest';
import type { Browser } from 'playwright-core';
import { collectPageErrors, launchChromium } from './browser';

let browser: Browser;
beforeAll(async () => {
  browser = await launchChromium();
});
afterAll(async () => {
  await browser?.close();
});

test('the app loads in Chromium without console errors', async () => {
  const page = await browser.newPage();
  const errors = collectPageErrors(page);
  await page.goto(inject('appUrl'));
  await page.getByRole('heading', { name: /Rungsmith/ }).first().waitFor();
  expect(await page.title()).toContain('Rungsmith');
  expect(errors).toEqual([]);
  await page.close();
});
