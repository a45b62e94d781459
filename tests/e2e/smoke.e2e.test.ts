import { expect, test } from 'vitest';
import { openApp, useChromium } from './appPage';

const browser = useChromium();

test('the app loads in Chromium without console errors', async () => {
  const { page, errors } = await openApp(browser());
  expect(await page.title()).toContain('Rungsmith');
  expect(errors).toEqual([]);
  await page.close();
});
