// Page object for the editor's panels (variables, inspector, problems) and the File menu.
import type { Browser, Locator, Page } from 'playwright-core';
import type { Project } from '../../src/model/project';
import type { UiState } from '../../src/store/uiStore';
import { expect } from 'vitest';
import { appUrl, chooseMenuItem, waitForApp } from './appPage';
import { collectPageErrors } from './browser';

/** expect.poll with room for the checks: they run after a quiet time, in an idle moment, in a worker. */
export const poll = <T>(fn: () => T | Promise<T>) => expect.poll(fn, { timeout: 10_000 });

export class EditorPage {
  readonly errors: string[];
  constructor(readonly page: Page) {
    this.errors = collectPageErrors(page);
  }

  /** Opens the app (the built preview unless `url` says otherwise) in its own context that accepts downloads. */
  static async open(browser: Browser, url: string = appUrl()): Promise<EditorPage> {
    const context = await browser.newContext({ acceptDownloads: true });
    const page = await context.newPage();
    const editor = new EditorPage(page);
    await page.goto(url);
    await waitForApp(page);
    return editor;
  }

  async close() {
    await this.page.context().close();
  }

  tab(name: 'Inspector' | 'Variables' | 'Problems'): Promise<void> {
    return this.page.getByRole('tab', { name, exact: true }).click();
  }

  get variables(): Locator {
    return this.page.getByTestId('variables-panel');
  }

  get problems(): Locator {
    return this.page.getByTestId('problems-panel');
  }

  get inspector(): Locator {
    return this.page.getByTestId('inspector-panel');
  }

  variableRow(name: string): Locator {
    return this.variables.getByTestId(`variable-row-${name}`);
  }

  /** Adds a row with "Add variable", names it and fills the given fields, committing each with Enter. */
  async declare(
    name: string,
    fields: { type?: string; address?: string; initial?: string; comment?: string } = {},
  ) {
    await this.variables.getByRole('button', { name: 'Add variable' }).click();
    const nameField = this.variables.locator('input[aria-label="Name"]:focus');
    await nameField.fill(name);
    await nameField.press('Enter');
    const row = this.variableRow(name);
    if (fields.type) await row.getByLabel('Type').selectOption(fields.type);
    if (fields.address !== undefined) await this.fill(row.getByLabel('Address'), fields.address);
    if (fields.initial !== undefined) await this.fill(row.getByLabel('Initial value'), fields.initial);
    if (fields.comment !== undefined) await this.fill(row.getByLabel('Comment'), fields.comment);
  }

  async fill(field: Locator, text: string) {
    await field.click();
    await field.fill(text);
    await field.press('Enter');
  }

  menu(menu: string, item: string): Promise<void> {
    return chooseMenuItem(this.page, menu, item);
  }

  /** Runs a menu item that opens the browser's file chooser and picks a file holding `text`. */
  async chooseFile(menu: string, item: string, file: { name: string; mimeType: string; text: string }) {
    const chooser = this.page.waitForEvent('filechooser');
    await this.menu(menu, item);
    const { name, mimeType, text } = file;
    await (await chooser).setFiles({ name, mimeType, buffer: Buffer.from(text) });
  }

  /** Does what starts a download (a menu item, a shortcut) and returns the file's suggested name and text. */
  async download(start: () => Promise<void>): Promise<{ name: string; text: string }> {
    const download = this.page.waitForEvent('download');
    await start();
    const file = await download;
    // Read through playwright's connection: the browser is the run's shared one (no local path).
    const chunks: Buffer[] = [];
    for await (const chunk of await file.createReadStream()) chunks.push(chunk as Buffer);
    return { name: file.suggestedFilename(), text: Buffer.concat(chunks).toString('utf8') };
  }

  /** File > Open… with a file the user picks in the browser's file chooser. */
  openFile(name: string, text: string): Promise<void> {
    return this.chooseFile('File', 'Open…', { name, mimeType: 'application/json', text });
  }

  project(): Promise<Project> {
    return this.page.evaluate(() => window.rungsmith!.documentStore!.getState().project);
  }

  selection(): Promise<UiState['selection']> {
    return this.page.evaluate(() => window.rungsmith!.uiStore!.getState().selection);
  }

  /** Clears or sets the selection directly (a test set-up step, not what is being tested). */
  uiSelect(network: string | undefined, elements: string[]): Promise<void> {
    return this.page.evaluate(
      ([n, els]) => window.rungsmith!.uiStore!.getState().select(n as never, els as never),
      [network, elements] as const,
    );
  }

  /** Waits until the autosave has written the current document to IndexedDB. */
  async waitForAutosave() {
    await this.page.waitForFunction(() => {
      const status = document.querySelector('[data-testid="autosave-status"]');
      return (
        status?.getAttribute('data-pending') === 'false' && Number(status.getAttribute('data-saved-at')) > 0
      );
    });
  }
}
