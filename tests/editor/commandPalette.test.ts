// The command palette and the shortcut list are built from every command list of the app, and
// docs/keyboard.md holds the list generated from them (so the two agree).
import { readFileSync, writeFileSync } from 'node:fs';
import { describe, expect, test } from 'vitest';
import { allCommands, availability, filterCommands, fuzzyScore, shortcutGroups, shortcutMarkdown } from '../../src/editor/commands/allCommands';
import { COMMANDS } from '../../src/editor/commands/registry';
import { SIM_COMMANDS, simControls } from '../../src/editor/commands/simCommands';
import type { EditorContext } from '../../src/editor/commands/editorActions';
import type { SimStore } from '../../src/store/simState';
import { FILE_MENU_COMMANDS } from '../../src/editor/files/FileMenu';
import { SHELL_COMMANDS } from '../../src/editor/layout/shellCommands';

const DOC = 'docs/keyboard.md';
const BEGIN = '<!-- shortcuts: generated from the command registry (tests/editor/commandPalette.test.ts) -->';
const END = '<!-- end of generated shortcuts -->';
/** Table text without the padding Prettier adds (`npm run format` aligns the columns). */
const normalise = (md: string) =>
  md
    .split('\n')
    .map((line) => line.replace(/\s*\|\s*/g, '|').replace(/-{3,}/g, '---').trimEnd())
    .join('\n');

describe('every command', () => {
  test('the registry, the File menu, the shell and the simulator commands are all in the palette, once each', () => {
    const ids = allCommands().map((c) => c.id);
    for (const c of [...COMMANDS, ...FILE_MENU_COMMANDS, ...SHELL_COMMANDS, ...SIM_COMMANDS]) expect(ids).toContain(c.id);
    expect(new Set(ids).size).toBe(ids.length);
  });

  test('CODESYS keys: F5 run, Shift+F5 stop, F9 breakpoint, F10/F11 step, Ctrl+F7 write, F7 force; ? and Ctrl+Shift+P', () => {
    const keys = new Map(allCommands().map((c) => [c.id, c.keys[0]]));
    expect(keys.get('sim.run')).toBe('f5');
    expect(keys.get('sim.stop')).toBe('shift+f5');
    expect(keys.get('sim.toggleBreakpoint')).toBe('f9');
    expect(keys.get('sim.stepOver')).toBe('f10');
    expect(keys.get('sim.stepInto')).toBe('f11');
    expect(keys.get('sim.writeValues')).toBe('mod+f7');
    expect(keys.get('sim.forceValues')).toBe('f7');
    expect(keys.get('help.shortcuts')).toBe('?');
    expect(keys.get('help.palette')).toBe('mod+shift+p');
  });

  test('no two commands share a key', () => {
    const seen = new Map<string, string>();
    for (const c of allCommands())
      for (const k of c.keys) {
        expect(seen.get(k), `${k}: ${c.id} and ${seen.get(k)}`).toBeUndefined();
        seen.set(k, c.id);
      }
  });
});

describe('fuzzy filter', () => {
  test('characters in order match; a whole word at the start ranks first', () => {
    expect(fuzzyScore('brk', 'Toggle breakpoint on the network')).toBeDefined();
    expect(fuzzyScore('xyz', 'Toggle breakpoint on the network')).toBeUndefined();
    const found = filterCommands(allCommands(), 'toggle breakpoint');
    expect(found[0]!.id).toBe('sim.toggleBreakpoint');
    expect(filterCommands(allCommands(), 'undo')[0]!.id).toBe('edit.undo');
    // By its key too.
    expect(filterCommands(allCommands(), 'F9').map((c) => c.id)).toContain('sim.toggleBreakpoint');
  });
});

describe('docs/keyboard.md', () => {
  test('holds the shortcut list generated from the commands (UPDATE_KEYBOARD_DOC=1 rewrites it)', () => {
    const doc = readFileSync(DOC, 'utf8');
    const begin = doc.indexOf(BEGIN);
    const end = doc.indexOf(END);
    expect(begin, `${DOC} lacks the marker ${BEGIN}`).toBeGreaterThanOrEqual(0);
    const generated = `${BEGIN}\n\n${shortcutMarkdown(allCommands())}\n\n${END}`;
    const current = doc.slice(begin, end + END.length);
    if (normalise(current) !== normalise(generated) && process.env.UPDATE_KEYBOARD_DOC === '1') writeFileSync(DOC, doc.slice(0, begin) + generated + doc.slice(end + END.length));
    else expect(normalise(current), `${DOC} is out of date: run UPDATE_KEYBOARD_DOC=1 npx vitest run tests/editor/commandPalette.test.ts`).toBe(normalise(generated));
    expect(shortcutGroups(allCommands()).map((g) => g.group)).toContain('Simulation');
  });
});

describe('Apply changes… (Alt+F8)', () => {
  const apply = allCommands().find((c) => c.id === 'sim.applyChanges')!;
  /** Its availability with the simulator in this state (only what the command reads). */
  const reason = (state: { onlineMode: 'edit' | 'request'; live: boolean; runningProgram: string | null; unapplied?: object }) => {
    const sim = { getState: () => ({ onlineChange: undefined, unapplied: undefined, ...state }) } as unknown as SimStore;
    simControls.current = { sim, commands: {} as never, project: () => ({}) as never };
    try {
      return availability(apply, {} as EditorContext);
    } finally {
      simControls.current = undefined;
    }
  };

  test('says why it has nothing to do without claiming the running program is the one shown when it may not be', () => {
    // Apply as you edit, running, the last edit not applied because of its errors: the program shown is not the one running.
    expect(reason({ onlineMode: 'edit', live: true, runningProgram: 'p1' })).toEqual({
      enabled: false,
      reason: 'Edits are applied as you make them (Online change: apply as you edit, in the Project inspector); an edit with errors is not applied until it is fixed.',
    });
    expect(reason({ onlineMode: 'request', live: false, runningProgram: null }).reason).toBe('Nothing is running: Run starts the program shown.');
    expect(reason({ onlineMode: 'request', live: true, runningProgram: 'p1' }).reason).toBe('The running program is the one shown: nothing to apply.');
    expect(reason({ onlineMode: 'request', live: true, runningProgram: 'p1', unapplied: { count: 1 } })).toEqual({ enabled: true });
  });
});
