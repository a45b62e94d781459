// "Name + Add" bar of the watch table and the trend: a text field that completes from the program's
// readable names as it is typed (variables, globals, FB instance members `Conv1.Motor`, nested ones,
// array elements: completeWatchName), in a list below the field that the keyboard drives (↓/↑ move,
// Enter adds the highlighted name, Tab puts it in the field to type on, Escape closes the list).
// Enter without a highlighted name adds what is typed. In a configuration (variables named by
// program instance) a short name resolves to its one instance path, and says which it picked; when
// several instances have it, nothing is guessed: the paths are listed to pick from (resolveWatchName).
import { useId, useMemo, useState } from 'react';
import type { SimVariable } from '../../sim/protocol';
import { completeWatchName, resolveWatchName } from '../../sim/watchNames';
import './sim.css';

export interface VariablePickerProps {
  /** Test ids "<testId>-add-name" (the field), "<testId>-add" (the button), "<testId>-choices" (the list), "<testId>-choice" (a name in it). */
  readonly testId: string;
  readonly placeholder: string;
  readonly label: string;
  readonly buttonLabel: string;
  readonly candidates: readonly SimVariable[];
  /** Program instances of the configuration that runs (variables named `Instance.Var`); empty outside one. */
  readonly instances?: readonly string[];
  /** What a suggestion shows beside the name. */
  readonly describe: (c: SimVariable) => string;
  /** Receives the typed text (or the instance path it resolves to); the field is cleared afterwards. */
  readonly onAdd: (text: string) => void;
}

export function VariablePicker(p: VariablePickerProps) {
  const [text, setText] = useState('');
  const [active, setActive] = useState(-1);
  const [open, setOpen] = useState(true);
  /** The last short name resolved to an instance path on adding: said beside the field. */
  const [picked, setPicked] = useState<string | undefined>(undefined);
  const listId = useId();
  const names = useMemo(() => p.candidates.map((c) => c.name), [p.candidates]);
  const byName = useMemo(() => new Map(p.candidates.map((c) => [c.name, c])), [p.candidates]);
  const resolved = useMemo(() => resolveWatchName(text, names, p.instances ?? []), [text, names, p.instances]);
  // A short name two instances have: nothing is added until one path is picked.
  const ambiguous = resolved.name === undefined && resolved.choices.some((c) => c.toUpperCase().endsWith(`.${text.trim().toUpperCase()}`));
  const shortNames = resolved.choices.length > 0;
  const list = useMemo(
    () => (shortNames ? resolved.choices : completeWatchName(text, names)),
    [shortNames, resolved.choices, text, names],
  );
  const shown = open && list.length > 0 && !(list.length === 1 && list[0] === resolved.name && text.trim() === resolved.name);
  const addName = (name: string) => {
    const typed = text.trim();
    p.onAdd(name);
    setPicked(typed && name.toUpperCase() !== typed.toUpperCase() && name.toUpperCase().endsWith(`.${typed.toUpperCase()}`) ? `${typed} → ${name}` : undefined);
    setText('');
    setActive(-1);
  };
  const add = () => {
    if (ambiguous) return;
    const name = resolved.name ?? text;
    if (name.trim()) addName(name);
  };
  const type = (value: string) => {
    setText(value);
    setActive(-1);
    setOpen(true);
    setPicked(undefined);
  };
  const onKeyDown = (e: React.KeyboardEvent<HTMLInputElement>) => {
    const n = shown ? list.length : 0;
    if (e.key === 'ArrowDown' && list.length > 0) {
      e.preventDefault();
      setOpen(true);
      setActive(shown ? (active + 1) % n : 0);
    } else if (e.key === 'ArrowUp' && n > 0) {
      e.preventDefault();
      setActive(active <= 0 ? n - 1 : active - 1);
    } else if (e.key === 'Enter') {
      e.preventDefault();
      if (shown && active >= 0) addName(list[active]!);
      else add();
    } else if (e.key === 'Tab' && shown && active >= 0 && !e.shiftKey) {
      // Into the field, to type on (`Conv1.` then its members).
      e.preventDefault();
      type(list[active]!);
    } else if (e.key === 'Escape' && shown) {
      e.preventDefault();
      e.stopPropagation();
      setOpen(false);
      setActive(-1);
    }
  };
  const describe = (name: string) => {
    const c = byName.get(name);
    return c ? p.describe(c) : '';
  };
  const optionId = (i: number) => `${listId}-${i}`;
  return (
    <>
      <input className="rs-sim-text" placeholder={p.placeholder} aria-label={p.label} value={text}
        role="combobox" aria-autocomplete="list" aria-expanded={shown} aria-controls={listId}
        aria-activedescendant={shown && active >= 0 ? optionId(active) : undefined}
        onChange={(e) => type(e.target.value)} onKeyDown={onKeyDown} data-testid={`${p.testId}-add-name`} />
      <button type="button" className="rs-sim-btn" onClick={add} disabled={ambiguous}
        title={ambiguous ? `${text.trim()} is in more than one program instance: pick one below` : undefined} data-testid={`${p.testId}-add`}>
        {p.buttonLabel}
      </button>
      {picked && !text ? (
        <span className="rs-sim-unit" role="status" data-testid={`${p.testId}-picked`}>{picked}</span>
      ) : null}
      {shown ? (
        <div className="rs-sim-choices" role="listbox" id={listId}
          aria-label={shortNames ? `Instance paths for ${text.trim()}` : `Names starting ${text.trim()}`} data-testid={`${p.testId}-choices`}>
          {shortNames ? (
            <span className="rs-sim-unit">{ambiguous ? `${text.trim()} is in several instances:` : resolved.name ? 'adds' : 'in instances:'}</span>
          ) : null}
          {list.map((c, i) => (
            <button key={c} id={optionId(i)} type="button" role="option" tabIndex={-1}
              aria-selected={active >= 0 ? i === active : c === resolved.name}
              className={i === active ? 'rs-sim-choice rs-sim-choice-active' : 'rs-sim-choice'}
              title={describe(c)} onMouseDown={(e) => e.preventDefault()} onClick={() => addName(c)} data-testid={`${p.testId}-choice`}>
              {c}
            </button>
          ))}
        </div>
      ) : null}
    </>
  );
}
