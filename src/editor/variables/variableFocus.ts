// "Show this variable in the table": the problems list asks, the variable table answers by
// switching to the right list and focusing the row's name field.
import { createStore } from 'zustand/vanilla';

export interface VariableFocusRequest {
  readonly name: string;
  readonly globals: boolean;
  readonly seq: number;
}

export const variableFocus = createStore<{ request: VariableFocusRequest | undefined }>()(() => ({
  request: undefined,
}));

let seq = 0;
export function focusVariable(name: string, globals: boolean): void {
  seq += 1;
  variableFocus.setState({ request: { name, globals, seq } });
  // The table lives in a tab of the side panel: bring that tab to the front.
  document.getElementById('rs-tab-variables')?.click();
}
