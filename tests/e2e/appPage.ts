// Shared set-up of the browser tests: a connection per test file to the run's one Chromium, the
// URL of this worker's app server, and the app opened in a page that records console errors.
import type { Browser, Locator, Page } from 'playwright-core';
import { afterAll, beforeAll, expect, inject } from 'vitest';
import { collectPageErrors, connectChromium } from './browser';

/** This worker's index among the run's servers (VITEST_POOL_ID is 1, 2, … up to maxWorkers). */
function worker(count: number): number {
  const id = Number(process.env.VITEST_POOL_ID ?? 1);
  if (!Number.isInteger(id) || id < 1 || id > count) throw new Error(`VITEST_POOL_ID ${process.env.VITEST_POOL_ID} has no app server (the global setup started ${count})`);
  return id - 1;
}

/**
 * The app's URL on this worker's server (tests/e2e/global-setup.ts): the URL the server `npm start`
 * runs printed, http://127.0.0.1:PORT/#token=…. Files running at the same time never share a server.
 */
export function appUrl(): string {
  const urls = inject('appUrls');
  return urls[worker(urls.length)]!;
}

/** The Modbus TCP port of this worker's server's simulated I/O device (127.0.0.1). */
export function simModbusPort(): number {
  const ports = inject('simModbusPorts');
  return ports[worker(ports.length)]!;
}

/** The window size the canvas tests lay the ladder out in. */
export const APP_VIEWPORT = { width: 1440, height: 900 } as const;

/**
 * Connects to the run's Chromium (tests/e2e/global-setup.ts) before the tests of the calling file
 * (or describe block) and disconnects after them, closing every page it opened, so after-hooks
 * registered later still see it open. Each page is in a context of its own (no shared storage).
 * Returns the connected browser.
 */
export function useChromium(): () => Browser {
  let browser: Browser | undefined;
  beforeAll(async () => {
    browser = await connectChromium(inject('browserWsEndpoint'));
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
export async function openApp(browser: Browser, url: string = appUrl()): Promise<AppPage> {
  const page = await browser.newPage({ viewport: APP_VIEWPORT });
  const errors = collectPageErrors(page);
  await page.goto(url);
  await waitForApp(page);
  return { page, errors };
}

/**
 * The element's box once it has stopped moving (the same in two reads 100 ms apart), e.g. a chart
 * resizing to its panel: a condition, where a fixed sleep would be too short on a busy machine.
 */
export async function settledBox(locator: Locator): Promise<{ x: number; y: number; width: number; height: number }> {
  let last: string | undefined;
  let box: { x: number; y: number; width: number; height: number } | null = null;
  await expect
    .poll(
      async () => {
        box = await locator.boundingBox();
        const text = JSON.stringify(box);
        const settled = box !== null && box.width > 0 && text === last;
        last = text;
        return settled;
      },
      { timeout: 30_000, interval: 100 },
    )
    .toBe(true);
  return box!;
}
