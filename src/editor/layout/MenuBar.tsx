// The top bar's menus, built from the command registry (and the File commands), with the
// shortcut of each command shown beside it.
import { useEffect, useRef, useState, type KeyboardEvent } from 'react';
import type { EditorContext } from '../commands/editorActions';
import { keyLabel } from '../commands/keys';
import { COMMANDS, type CommandGroup } from '../commands/registry';
import { FILE_MENU_COMMANDS } from '../files/FileMenu';
import { SHELL_COMMANDS } from './shellCommands';
import { HELP_COMMANDS } from '../commands/allCommands';

interface MenuItem {
  readonly id: string;
  readonly label: string;
  readonly shortcut?: string;
  readonly title?: string;
  readonly separatorBefore?: boolean;
  /** A view option: shown with a check mark when on. */
  checked?(): boolean;
  enabled(): boolean;
  run(): void;
}

interface Menu {
  readonly name: string;
  readonly items: readonly MenuItem[];
}

/** Print goes after the File menu's own commands and PLCopen import/export, before the examples. */
const FIRST_EXAMPLE = FILE_MENU_COMMANDS.findIndex((c) => c.group === 'Examples');
const FILE_PRINT_AFTER = FIRST_EXAMPLE < 0 ? FILE_MENU_COMMANDS.length : FIRST_EXAMPLE;

function buildMenus(ctx: EditorContext): Menu[] {
  const fileItems: MenuItem[] = FILE_MENU_COMMANDS.map((c, i) => ({
    id: c.id,
    label: c.group === 'Examples' ? `Example: ${c.label}` : c.label,
    ...(c.keys?.[0] ? { shortcut: keyLabel(c.keys[0]) } : {}),
    title: c.description,
    separatorBefore: i > 0 && c.group !== FILE_MENU_COMMANDS[i - 1]!.group,
    enabled: () => true,
    run: () => c.run(ctx),
  }));
  const shell = (menu: 'File' | 'View'): MenuItem[] =>
    SHELL_COMMANDS.filter((c) => c.menu === menu).map((c, i) => ({
      id: c.id,
      label: c.label,
      ...(c.keys?.[0] ? { shortcut: keyLabel(c.keys[0]) } : {}),
      title: c.description,
      separatorBefore: i === 0,
      enabled: () => true,
      run: () => c.run(ctx),
    }));
  const group = (g: CommandGroup): MenuItem[] =>
    COMMANDS.filter((c) => c.group === g && c.inMenu).map((c) => ({
      id: c.id,
      label: c.label,
      ...(c.keys?.[0] ? { shortcut: keyLabel(c.keys[0]) } : {}),
      enabled: () => (c.enabled ? c.enabled(ctx) : true),
      ...(c.checked ? { checked: () => c.checked!(ctx) } : {}),
      run: () => c.run(ctx),
    }));
  // The command palette and the list of shortcuts, at the end of the View menu.
  const help: MenuItem[] = HELP_COMMANDS.map((c, i) => ({
    id: c.id,
    label: c.label,
    ...(c.keys[0] ? { shortcut: keyLabel(c.keys[0]) } : {}),
    ...(c.description ? { title: c.description } : {}),
    separatorBefore: i === 0,
    enabled: () => true,
    run: () => c.run(ctx),
  }));
  return [
    { name: 'File', items: [...fileItems.slice(0, FILE_PRINT_AFTER), ...shell('File'), ...fileItems.slice(FILE_PRINT_AFTER)] },
    { name: 'Edit', items: group('Edit') },
    { name: 'Insert', items: group('Insert') },
    { name: 'Network', items: group('Network') },
    { name: 'View', items: [...group('View'), ...shell('View'), ...help] },
  ];
}

export function MenuBar({ ctx }: { readonly ctx: EditorContext }) {
  const [open, setOpen] = useState<string | undefined>(undefined);
  const ref = useRef<HTMLElement>(null);
  const menus = buildMenus(ctx);

  useEffect(() => {
    if (!open) return undefined;
    const onDown = (e: MouseEvent) => {
      if (!ref.current?.contains(e.target as Node)) setOpen(undefined);
    };
    document.addEventListener('mousedown', onDown);
    return () => document.removeEventListener('mousedown', onDown);
  }, [open]);

  useEffect(() => {
    if (open) ref.current?.querySelector<HTMLElement>('[role="menuitem"]:not([disabled])')?.focus();
  }, [open]);

  const onMenuKeyDown = (e: KeyboardEvent) => {
    e.stopPropagation();
    const items = [
      ...(ref.current?.querySelectorAll<HTMLElement>('[role="menuitem"]:not([disabled])') ?? []),
    ];
    const i = items.indexOf(document.activeElement as HTMLElement);
    if (e.key === 'Escape') {
      setOpen(undefined);
      document.getElementById(`rs-menu-${open}`)?.focus();
    } else if (e.key === 'ArrowDown' || e.key === 'ArrowUp') {
      e.preventDefault();
      items[(i + (e.key === 'ArrowDown' ? 1 : -1) + items.length) % items.length]?.focus();
    } else if (e.key === 'ArrowRight' || e.key === 'ArrowLeft') {
      const m = menus.findIndex((x) => x.name === open);
      setOpen(menus[(m + (e.key === 'ArrowRight' ? 1 : -1) + menus.length) % menus.length]!.name);
    }
  };

  return (
    <nav className="rs-menubar" ref={ref} aria-label="Main menu">
      {menus.map((menu) => (
        <div key={menu.name} className="rs-menu">
          <button
            id={`rs-menu-${menu.name}`}
            type="button"
            className="rs-menu-button"
            aria-haspopup="menu"
            aria-expanded={open === menu.name}
            data-testid={`menu-${menu.name.toLowerCase()}`}
            onClick={() => setOpen(open === menu.name ? undefined : menu.name)}
            onMouseEnter={() => open && setOpen(menu.name)}
          >
            {menu.name}
          </button>
          {open === menu.name && (
            <div role="menu" aria-label={menu.name} className="rs-menu-list" onKeyDown={onMenuKeyDown}>
              {menu.items.map((item) => (
                <button
                  key={item.id}
                  type="button"
                  role="menuitem"
                  className={`rs-menu-item${item.separatorBefore ? ' rs-separator' : ''}`}
                  disabled={!item.enabled()}
                  title={item.title}
                  data-testid={`menuitem-${item.id}`}
                  data-checked={item.checked ? String(item.checked()) : undefined}
                  onClick={() => {
                    setOpen(undefined);
                    item.run();
                  }}
                >
                  <span>
                    {item.checked && <span className="rs-menu-check" aria-hidden>{item.checked() ? '✓ ' : '\u2003'}</span>}
                    {item.label}
                    {item.checked && <span className="rs-visually-hidden">{item.checked() ? ' (on)' : ' (off)'}</span>}
                  </span>
                  {item.shortcut && <kbd>{item.shortcut}</kbd>}
                </button>
              ))}
            </div>
          )}
        </div>
      ))}
    </nav>
  );
}
