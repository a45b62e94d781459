// "Name + Add" bar of the watch table and the trend: a text field completing from the program's
// readable names, added on Enter or with the button.
import { useState } from 'react';
import type { SimVariable } from '../../sim/protocol';
import './sim.css';

export interface VariablePickerProps {
  /** Test ids "<testId>-add-name" (the field) and "<testId>-add" (the button); the datalist is "rs-<testId>-candidates". */
  readonly testId: string;
  readonly placeholder: string;
  readonly label: string;
  readonly buttonLabel: string;
  readonly candidates: readonly SimVariable[];
  /** What a suggestion shows beside the name. */
  readonly describe: (c: SimVariable) => string;
  /** Receives the typed text; the field is cleared afterwards. */
  readonly onAdd: (text: string) => void;
}

export function VariablePicker(p: VariablePickerProps) {
  const [text, setText] = useState('');
  const listId = `rs-${p.testId}-candidates`;
  const add = () => {
    p.onAdd(text);
    setText('');
  };
  return (
    <>
      <input className="rs-sim-text" list={listId} placeholder={p.placeholder} aria-label={p.label} value={text}
        onChange={(e) => setText(e.target.value)} onKeyDown={(e) => e.key === 'Enter' && add()} data-testid={`${p.testId}-add-name`} />
      <datalist id={listId}>
        {p.candidates.map((c) => <option key={c.name} value={c.name}>{p.describe(c)}</option>)}
      </datalist>
      <button type="button" className="rs-sim-btn" onClick={add} data-testid={`${p.testId}-add`}>{p.buttonLabel}</button>
    </>
  );
}
