// Shared set-up of the browser tests: one Chromium per test file, and the app opened in a page that
// records console errors.
import type { Browser, Page } from 'playwright-core';
import { afterAll, beforeAll, inject } from 'vitest';
import { collectPageErrors, launchChromium } from './browser';

/** The window size the canvas tests lay the ladder out in. */
export const APP_VIEWPORT = { width: 1440, height: 900 } as const;

/**
 * Launches Chromium before the tests of the calling file (or describe block) and closes it after
 * them, so after-hooks registered later still see it open. Returns the running browser.
 */
export function useChromium(): () => Browser {
  let browser: Browser | undefined;
  beforeAll(async () => {
    browser = await launchChromium();
  });
  afterAll(async () => {
    await browser?.close();
  });
  return () => {
    if (!browser) throw new Error('Chromium is not running yet: use the browser inside a test or hook');
    return browser;
  };
}

/** Waits until the editor has mounted (its heading is on the page). */
export async function waitForApp(page: Page): Promise<void> {
  await page
    .getByRole('heading', { name: /Rungsmith/ })
    .first()
    .waitFor();
}

/** Opens a menu of the menu bar ("File") and clicks one of its items. */
export async function chooseMenuItem(page: Page, menu: string, item: string): Promise<void> {
  await page.getByTestId(`menu-${menu.toLowerCase()}`).click();
  await page.getByRole('menuitem', { name: item }).click();
}

export interface AppPage {
  readonly page: Page;
  /** Console errors and uncaught page errors seen so far. */
  readonly errors: string[];
}

/** Opens the app (the built preview unless `url` says otherwise) in a new page and waits for it. */
export async function openApp(browser: Browser, url: string = inject('appUrl')): Promise<AppPage> {
  const page = await browser.newPage({ viewport: APP_VIEWPORT });
  const errors = collectPageErrors(page);
  await page.goto(url);
  await waitForApp(page);
  return { page, errors };
}
