// "Name + Add" bar of the watch table and the trend: a text field completing from the program's
// readable names, added on Enter or with the button. In a configuration (variables named by program
// instance) a short name resolves to its one instance path, and the instance paths it may mean are
// listed below the field as it is typed (resolveWatchName).
import { useMemo, useState } from 'react';
import type { SimVariable } from '../../sim/protocol';
import { resolveWatchName } from '../../sim/watchNames';
import './sim.css';

export interface VariablePickerProps {
  /** Test ids "<testId>-add-name" (the field) and "<testId>-add" (the button); the datalist is "rs-<testId>-candidates". */
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
  const listId = `rs-${p.testId}-candidates`;
  const names = useMemo(() => p.candidates.map((c) => c.name), [p.candidates]);
  const resolved = useMemo(() => resolveWatchName(text, names, p.instances ?? []), [text, names, p.instances]);
  // A short name two instances have: nothing is added until one path is picked.
  const ambiguous = resolved.name === undefined && resolved.choices.some((c) => c.toUpperCase().endsWith(`.${text.trim().toUpperCase()}`));
  const addName = (name: string) => {
    p.onAdd(name);
    setText('');
  };
  const add = () => {
    if (ambiguous) return;
    addName(resolved.name ?? text);
  };
  const describe = (name: string) => {
    const c = p.candidates.find((x) => x.name === name);
    return c ? p.describe(c) : '';
  };
  const offer = resolved.choices.length > 0 && !(resolved.choices.length === 1 && resolved.choices[0] === resolved.name && text.trim() === resolved.name);
  return (
    <>
      <input className="rs-sim-text" list={listId} placeholder={p.placeholder} aria-label={p.label} value={text}
        onChange={(e) => setText(e.target.value)} onKeyDown={(e) => e.key === 'Enter' && add()} data-testid={`${p.testId}-add-name`} />
      <datalist id={listId}>
        {p.candidates.map((c) => <option key={c.name} value={c.name}>{p.describe(c)}</option>)}
      </datalist>
      <button type="button" className="rs-sim-btn" onClick={add} disabled={ambiguous}
        title={ambiguous ? `${text.trim()} is in more than one program instance: pick one below` : undefined} data-testid={`${p.testId}-add`}>
        {p.buttonLabel}
      </button>
      {offer ? (
        <div className="rs-sim-choices" role="listbox" aria-label={`Instance paths for ${text.trim()}`} data-testid={`${p.testId}-choices`}>
          <span className="rs-sim-unit">{ambiguous ? `${text.trim()} is in several instances:` : resolved.name ? 'adds' : 'in instances:'}</span>
          {resolved.choices.map((c) => (
            <button key={c} type="button" role="option" aria-selected={c === resolved.name} className="rs-sim-choice"
              title={describe(c)} onClick={() => addName(c)} data-testid={`${p.testId}-choice`}>
              {c}
            </button>
          ))}
        </div>
      ) : null}
    </>
  );
}
