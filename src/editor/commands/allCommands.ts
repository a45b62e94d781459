// Every command of the app in one list, for the command palette (Ctrl+Shift+P), the list of
// shortcuts (`?`) and docs/keyboard.md: the editor's registry (registry.ts), the File menu
// (FileMenu.ts), the shell's panel and print commands (shellCommands.ts), the simulator's
// (simCommands.ts) and these two. Built from those lists, so a command added to any of them is here
// with its keys.
import { createStore } from 'zustand/vanilla';
import { FILE_MENU_COMMANDS } from '../files/FileMenu';
import { SHELL_COMMANDS } from '../layout/shellCommands';
import type { EditorContext } from './editorActions';
import { keyLabel } from './keys';
import { COMMANDS } from './registry';
import { SIM_COMMANDS } from './simCommands';

export interface AppCommand {
  readonly id: string;
  readonly label: string;
  readonly group: string;
  /** Shortcut specs (keys.ts); the first is the one shown in menus. */
  readonly keys: readonly string[];
  readonly description?: string | undefined;
  run(ctx: EditorContext): void;
  enabled?(ctx: EditorContext): boolean;
  disabledReason?(ctx: EditorContext): string | undefined;
}

/** The palette or the shortcut list, whichever is open. */
export const commandUi = createStore<{ open: 'palette' | 'shortcuts' | undefined; show(what: 'palette' | 'shortcuts' | undefined): void }>()((set) => ({
  open: undefined,
  show: (open) => set({ open }),
}));

export const HELP_COMMANDS: readonly AppCommand[] = [
  {
    id: 'help.palette',
    label: 'Command palette…',
    group: 'Help',
    keys: ['mod+shift+p'],
    description: 'Find any command by name and run it',
    run: () => commandUi.getState().show('palette'),
  },
  {
    id: 'help.shortcuts',
    label: 'Keyboard shortcuts',
    group: 'Help',
    keys: ['?'],
    description: 'Every shortcut, grouped and searchable (while simulating with an element selected, ? asks "Why?")',
    run: () => commandUi.getState().show('shortcuts'),
  },
];

/** Why a registry command that does not say is disabled, where it is plain. */
const REASONS: Record<string, string> = {
  'edit.undo': 'Nothing to undo.',
  'edit.redo': 'Nothing to redo.',
  'edit.cut': 'Select something or place the cursor first.',
  'edit.copy': 'Select something or place the cursor first.',
  'edit.duplicate': 'Select something or place the cursor first.',
  'edit.delete': 'Select something or place the cursor first.',
  'edit.branch': 'Select something or place the cursor first.',
  'network.moveUp': 'Select whole networks first (click their headers).',
  'network.moveDown': 'Select whole networks first (click their headers).',
};

export function allCommands(): readonly AppCommand[] {
  const seen = new Set<string>();
  const list: AppCommand[] = [
    ...COMMANDS.map((c): AppCommand => ({
      id: c.id,
      label: c.label,
      group: c.group,
      keys: c.keys ?? [],
      run: (ctx) => c.run(ctx),
      ...(c.enabled ? { enabled: (ctx: EditorContext) => c.enabled!(ctx) } : {}),
      disabledReason: (ctx) => c.disabledReason?.(ctx) ?? REASONS[c.id],
    })),
    ...FILE_MENU_COMMANDS.map((c): AppCommand => ({
      id: c.id,
      label: c.group === 'Examples' ? `Example: ${c.label}` : c.label,
      group: c.group,
      keys: c.keys ?? [],
      description: c.description,
      run: (ctx) => c.run(ctx),
    })),
    ...SHELL_COMMANDS.map((c): AppCommand => ({ id: c.id, label: c.label, group: c.menu, keys: c.keys ?? [], description: c.description, run: (ctx) => c.run(ctx) })),
    ...SIM_COMMANDS.map((c): AppCommand => ({ ...c, keys: c.keys ?? [] })),
    ...HELP_COMMANDS,
  ];
  return list.filter((c) => !seen.has(c.id) && (seen.add(c.id), true));
}

/** Enabled, or the reason it is not (a registry command that gives none: a plain "Not available now."). */
export function availability(c: AppCommand, ctx: EditorContext): { enabled: boolean; reason?: string } {
  if (!c.enabled || c.enabled(ctx)) return { enabled: true };
  return { enabled: false, reason: c.disabledReason?.(ctx) ?? 'Not available now.' };
}

/** A command's shortcuts as text: "Ctrl+Y, Ctrl+Shift+Z". */
export const keysText = (c: Pick<AppCommand, 'keys'>): string => c.keys.map(keyLabel).join(', ');

/**
 * Fuzzy match of a query in a text: every character of the query in order (case-insensitive);
 * undefined when it does not match, else a score (higher is better: a match at the start of the
 * text or of a word, and characters next to each other, score more).
 */
export function fuzzyScore(query: string, text: string): number | undefined {
  const q = query.trim().toLowerCase();
  if (!q) return 0;
  const t = text.toLowerCase();
  const whole = t.indexOf(q);
  if (whole >= 0) return 1000 - whole + (whole === 0 || /\W/.test(t[whole - 1]!) ? 500 : 0);
  let score = 0;
  let at = -1;
  for (const ch of q) {
    if (ch === ' ') continue;
    const next = t.indexOf(ch, at + 1);
    if (next < 0) return undefined;
    score += next === at + 1 ? 5 : next === 0 || /\W/.test(t[next - 1]!) ? 3 : 1;
    at = next;
  }
  return score;
}

/** The commands a query finds, best first: by label, then by group, id and keys. */
export function filterCommands(commands: readonly AppCommand[], query: string): AppCommand[] {
  if (!query.trim()) return [...commands];
  const scored = commands.flatMap((c) => {
    const label = fuzzyScore(query, c.label);
    const other = fuzzyScore(query, `${c.group} ${c.id} ${keysText(c)}`);
    const score = label !== undefined ? label + 100 : other;
    return score === undefined ? [] : [{ c, score }];
  });
  return scored.sort((a, b) => b.score - a.score).map((s) => s.c);
}

/** The commands with keys, grouped in the order their groups first appear. */
export function shortcutGroups(commands: readonly AppCommand[]): { group: string; commands: AppCommand[] }[] {
  const groups: { group: string; commands: AppCommand[] }[] = [];
  for (const c of commands) {
    if (c.keys.length === 0) continue;
    let g = groups.find((x) => x.group === c.group);
    if (!g) groups.push((g = { group: c.group, commands: [] }));
    g.commands.push(c);
  }
  return groups;
}

const mdCell = (text: string) => text.replace(/\|/g, '\\|');

/** The shortcut list as Markdown tables (docs/keyboard.md holds this text between its markers). */
export function shortcutMarkdown(commands: readonly AppCommand[]): string {
  return shortcutGroups(commands)
    .map(({ group, commands: list }) => {
      const rows = list.map((c) => `| ${c.keys.map((k) => `\`${mdCell(keyLabel(k))}\``).join(', ')} | ${mdCell(c.label)} |`);
      return [`### ${group}`, '', '| Key | Command |', '| --- | --- |', ...rows].join('\n');
    })
    .join('\n\n');
}
