// Mounted once by the app shell (panels.ts HOSTS): the simulator's keys (F5, Shift+F5, F7, Ctrl+F7,
// F9, F10, F11; simCommands.ts), the command palette (Ctrl+Shift+P) and the list of shortcuts (`?`),
// both built from every command the app has (allCommands.ts).
import { useEffect, useMemo, useRef, useState } from 'react';
import { useStore } from 'zustand';
import { useDocumentStore } from '../../store/documentStore';
import { useUiStore } from '../../store/uiStore';
import { useSimCommands } from '../hardware/useHardwareStepping';
import { isModalOpen, useModal } from '../layout/useModal';
import { useSimStore } from '../sim/simContext';
import { allCommands, availability, commandUi, filterCommands, HELP_COMMANDS, keysText, shortcutGroups, type AppCommand } from './allCommands';
import type { EditorContext } from './editorActions';
import { keyLabel, matches, parseKeys } from './keys';
import { SIM_COMMANDS, simControls } from './simCommands';
import { isTypingTarget } from './useShortcuts';
import '../files/modal.css';
import './commands.css';

const BINDINGS = [...SIM_COMMANDS.map((c): AppCommand => ({ ...c, keys: c.keys ?? [] })), ...HELP_COMMANDS].flatMap((command) =>
  command.keys.map((k) => ({ spec: parseKeys(k), command })),
);

/** Runs a command after the palette has closed (a command may open a dialog of its own). */
const runLater = (c: AppCommand, ctx: EditorContext) => setTimeout(() => c.run(ctx), 0);

export function CommandHost() {
  const doc = useDocumentStore();
  const ui = useUiStore();
  const ctx = useMemo<EditorContext>(() => ({ doc, ui }), [doc, ui]);
  const sim = useSimStore();
  const commands = useSimCommands();
  const open = useStore(commandUi, (s) => s.open);

  useEffect(() => {
    simControls.current = { sim, commands, project: () => doc.getState().project };
    return () => {
      simControls.current = undefined;
    };
  }, [sim, commands, doc]);

  useEffect(() => {
    const onKeyDown = (e: KeyboardEvent) => {
      if (e.defaultPrevented || isModalOpen()) return;
      const binding = BINDINGS.find((b) => matches(b.spec, e));
      if (!binding) return;
      const { command, spec } = binding;
      // Function keys type nothing: they work from a field too (Ctrl+F7 right after typing a
      // prepared value), and the browser's own use (F5 reload, F7 caret browsing, F11 full screen)
      // never happens in the app. Other keys leave fields and inline editing alone.
      const functionKey = /^f\d+$/.test(spec.key);
      const state = ui.getState();
      if (!functionKey && command.id !== 'help.palette' && (isTypingTarget(e.target) || state.editing || state.blockPicker || state.pastePrompt)) return;
      if (command.id === 'help.shortcuts') {
        // `?` asks "Why?" while simulating with an element selected (useWhyKey): the list only when it did not.
        setTimeout(() => {
          if (!e.defaultPrevented && !isModalOpen()) command.run(ctx);
        }, 0);
        return;
      }
      e.preventDefault();
      const a = availability(command, ctx);
      if (!a.enabled) {
        state.setStatus(`${command.label}: ${a.reason ?? 'not available now.'}`);
        return;
      }
      command.run(ctx);
    };
    // Under a dialog the keys do nothing, and neither does the browser (no reload by F5 from a dialog).
    const guard = (e: KeyboardEvent) => {
      if (isModalOpen() && BINDINGS.some((b) => /^f\d+$/.test(b.spec.key) && matches(b.spec, e))) e.preventDefault();
    };
    window.addEventListener('keydown', onKeyDown);
    window.addEventListener('keydown', guard, true);
    return () => {
      window.removeEventListener('keydown', onKeyDown);
      window.removeEventListener('keydown', guard, true);
    };
  }, [ctx, ui]);

  const close = () => commandUi.getState().show(undefined);
  if (open === 'palette') return <CommandPalette ctx={ctx} onClose={close} />;
  if (open === 'shortcuts') return <ShortcutList onClose={close} />;
  return null;
}

function CommandPalette({ ctx, onClose }: { ctx: EditorContext; onClose: () => void }) {
  const modal = useModal(onClose);
  const commands = useMemo(() => allCommands(), []);
  const [query, setQuery] = useState('');
  const [active, setActive] = useState(0);
  const [note, setNote] = useState<string>();
  const found = useMemo(() => filterCommands(commands, query), [commands, query]);
  const list = useRef<HTMLUListElement>(null);
  const current = Math.min(active, Math.max(0, found.length - 1));
  useEffect(() => {
    list.current?.querySelector(`[data-index="${current}"]`)?.scrollIntoView({ block: 'nearest' });
  }, [current]);
  const run = (c: AppCommand | undefined) => {
    if (!c) return;
    const a = availability(c, ctx);
    if (!a.enabled) {
      setNote(`${c.label}: ${a.reason}`);
      return;
    }
    onClose();
    runLater(c, ctx);
  };
  const onKey = (e: React.KeyboardEvent) => {
    const move = (to: number) => {
      e.preventDefault();
      setActive(found.length === 0 ? 0 : (to + found.length) % found.length);
      setNote(undefined);
    };
    if (e.key === 'ArrowDown') move(current + 1);
    else if (e.key === 'ArrowUp') move(current - 1);
    else if (e.key === 'PageDown') move(Math.min(found.length - 1, current + 10));
    else if (e.key === 'PageUp') move(Math.max(0, current - 10));
    else if (e.key === 'Home' && e.ctrlKey) move(0);
    else if (e.key === 'End' && e.ctrlKey) move(found.length - 1);
    else if (e.key === 'Enter') {
      e.preventDefault();
      run(found[current]);
    }
  };
  return (
    <div className="rs-modal-backdrop rs-cmdp-backdrop" onMouseDown={(e) => e.target === e.currentTarget && onClose()}>
      <div {...modal} className="rs-modal rs-cmdp" role="dialog" aria-modal="true" aria-label="Command palette" data-testid="command-palette">
        <input
          className="rs-cmdp-input"
          autoFocus
          role="combobox"
          aria-expanded="true"
          aria-controls="rs-cmdp-list"
          aria-activedescendant={found[current] ? `rs-cmdp-${current}` : undefined}
          aria-label="Command"
          placeholder="Type a command (fuzzy: “brk” finds Toggle breakpoint)"
          value={query}
          onChange={(e) => {
            setQuery(e.target.value);
            setActive(0);
            setNote(undefined);
          }}
          onKeyDown={onKey}
          data-testid="palette-input"
        />
        {note && <p className="rs-cmdp-note" role="alert" data-testid="palette-note">{note}</p>}
        <ul id="rs-cmdp-list" ref={list} className="rs-cmdp-list" role="listbox" aria-label="Commands">
          {found.map((c, i) => {
            const a = availability(c, ctx);
            return (
              <li
                key={c.id}
                id={`rs-cmdp-${i}`}
                data-index={i}
                role="option"
                aria-selected={i === current}
                aria-disabled={!a.enabled}
                className={`rs-cmdp-item${i === current ? ' rs-cmdp-active' : ''}${a.enabled ? '' : ' rs-cmdp-disabled'}`}
                title={a.enabled ? c.description : a.reason}
                data-testid={`palette-item-${c.id}`}
                onMouseMove={() => i !== current && setActive(i)}
                onClick={() => run(c)}
              >
                <span className="rs-cmdp-label">
                  <span className="rs-cmdp-group">{c.group}: </span>
                  {c.label}
                  {!a.enabled && <span className="rs-cmdp-reason"> — {a.reason}</span>}
                </span>
                {c.keys.length > 0 && <kbd className="rs-cmdp-keys">{keysText(c)}</kbd>}
              </li>
            );
          })}
          {found.length === 0 && <li className="rs-cmdp-empty">No command matches “{query}”.</li>}
        </ul>
      </div>
    </div>
  );
}

function ShortcutList({ onClose }: { onClose: () => void }) {
  const modal = useModal(onClose);
  const [query, setQuery] = useState('');
  const groups = useMemo(() => shortcutGroups(filterCommands(allCommands(), query).sort(byGroupOrder)), [query]);
  return (
    <div className="rs-modal-backdrop" onMouseDown={(e) => e.target === e.currentTarget && onClose()}>
      <div {...modal} className="rs-modal rs-shortcuts" role="dialog" aria-modal="true" aria-labelledby="rs-shortcuts-title" data-testid="shortcut-list">
        <h2 id="rs-shortcuts-title">Keyboard shortcuts</h2>
        <input className="rs-cmdp-input" autoFocus aria-label="Search shortcuts" placeholder="Search by command or key"
          value={query} onChange={(e) => setQuery(e.target.value)} data-testid="shortcut-search" />
        <div className="rs-shortcut-groups">
          {groups.map((g) => (
            <section key={g.group} aria-label={g.group}>
              <h3>{g.group}</h3>
              <table className="rs-shortcut-table">
                <tbody>
                  {g.commands.map((c) => (
                    <tr key={c.id} data-testid={`shortcut-${c.id}`}>
                      <td>{c.label}</td>
                      <td>{c.keys.map((k) => <kbd key={k}>{keyLabel(k)}</kbd>)}</td>
                    </tr>
                  ))}
                </tbody>
              </table>
            </section>
          ))}
          {groups.length === 0 && <p>No shortcut matches “{query}”.</p>}
        </div>
        <div className="rs-modal-buttons">
          <button type="button" className="rs-button" onClick={onClose}>Close</button>
        </div>
      </div>
    </div>
  );
}

/** Keeps the registry's order of groups while filtering ranks commands. */
const ORDER = new Map(allCommands().map((c, i) => [c.id, i]));
const byGroupOrder = (a: AppCommand, b: AppCommand) => (ORDER.get(a.id) ?? 0) - (ORDER.get(b.id) ?? 0);
