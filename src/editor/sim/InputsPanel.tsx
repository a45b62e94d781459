// Every %I input of the program with a switch (toggle) and a push-button (TRUE while held);
// word inputs take a typed value. Changes reach the PLC at its next input read.
// With hardware attached as controller, an input the gateway has as a point comes from the device:
// its switch, button and field are off, saying so (only a confirmed force, from the canvas's
// context menu or the Watch panel, overrides it). Likewise an input the project's machine (Plant
// panel) writes every scan, a sensor or an operator control: it comes from the machine.
import { useMemo, useState } from 'react';
import { parseLocation } from '../../model/iecTypes';
import { addressKey, mappedPoints } from '../../plant/loop';
import { plantById } from '../../plant/machines';
import type { SimState } from '../../store/simState';
import { selectProject, useDocument } from '../../store/documentStore';
import { fieldInputAddress, fieldInputWords } from '../hardware/fieldIo';
import { useGateway } from '../hardware/useGateway';
import { forcedText, liveText } from './liveValues';
import { ForcedBadge } from '../theme/ForcedBadge';
import { useSim, useSimStore } from './simContext';
import './sim.css';

interface InputRow {
  readonly name: string;
  readonly type: string;
  readonly location: string;
  readonly comment: string;
  /** The machine's words when its sensor or operator control is at this input: it writes it every scan. */
  readonly machine?: string;
}

export function InputsPanel() {
  const project = useDocument(selectProject);
  const inputs = useMemo<InputRow[]>(() => {
    const pou = project.pous.find((p) => p.kind === 'PROGRAM');
    const all = [...(pou?.variables ?? []), ...project.globals];
    const model = project.plant ? plantById(project.plant.id) : undefined;
    const points = new Map(
      (model ? mappedPoints(model, project.plant?.map) : [])
        .filter((p) => p.kind !== 'actuator')
        .map((p) => [addressKey(p.address), p] as const),
    );
    return all
      .filter((v) => v.location && parseLocation(v.location)?.area === 'I')
      .map((v) => {
        const point = points.get(addressKey(v.location!));
        const machine =
          model && point
            ? `Written by the machine ${model.id} every scan (its ${point.kind === 'operator' ? 'operator control' : 'sensor'} ${point.name}${point.kind === 'operator' ? ': press it on the drawing in the Plant panel' : ''}); a value set here would be overwritten. Only a force overrides it.`
            : undefined;
        return { name: v.name, type: v.type.toUpperCase(), location: v.location!, comment: v.comment, ...(machine ? { machine } : {}) };
      });
  }, [project]);
  return (
    <div className="rs-sim-panel" data-testid="inputs-panel">
      {inputs.length === 0 ? (
        <p className="rs-sim-empty">The program declares no inputs (%I addresses).</p>
      ) : (
        <table className="rs-sim-table" aria-label="Inputs">
          <tbody>
            {inputs.map((row) => (row.type === 'BOOL' ? <BoolInput key={row.name} row={row} /> : <WordInput key={row.name} row={row} />))}
          </tbody>
        </table>
      )}
    </div>
  );
}

function Label({ row }: { row: InputRow }) {
  return (
    <td title={row.comment || undefined}>
      <span className="rs-sim-name">{row.name}</span> <span className="rs-sim-unit">{row.location}</span>
    </td>
  );
}

/** The device address behind this input while hardware is attached, else undefined. */
function useFieldInput(name: string): string | undefined {
  const variable = useSim((s: SimState) => s.layout?.variables[s.variableIndex.get(name.toUpperCase()) ?? -1]);
  return fieldInputAddress(variable, useGateway());
}

function BoolInput({ row }: { row: InputRow }) {
  const sim = useSimStore();
  const field = useFieldInput(row.name);
  const value = useSim((s) => liveText(s, row.name));
  const forced = useSim((s) => forcedText(s, row.name));
  const on = value === 'TRUE';
  const release = () => sim.getState().releaseInput(row.name);
  const machine = field ? undefined : row.machine;
  return (
    <tr data-testid={`input-${row.name}`}>
      <Label row={row} />
      <td>
        <button type="button" role="switch" aria-checked={on} aria-label={`${row.name} switch`} disabled={value === undefined || field !== undefined || machine !== undefined}
          title={field ? fieldInputWords(field, row.name) : machine}
          className={`rs-sim-switch${on ? ' rs-sim-on' : ''}`} onClick={() => sim.getState().toggleInput(row.name)} data-testid="input-switch">
          {value === undefined ? '—' : on ? 'ON' : 'OFF'}
        </button>
        {/* Forced: the badge the watch table and the canvas show (the switch shows the forced value). */}
        {forced !== undefined && <ForcedBadge title={`forced to ${forced}`} />}
      </td>
      <td>
        <button type="button" className="rs-sim-btn" disabled={value === undefined || field !== undefined || machine !== undefined}
          title={field ? fieldInputWords(field, row.name) : (machine ?? 'Push-button: ON while the mouse button is held')}
          onPointerDown={(e) => {
            e.currentTarget.setPointerCapture(e.pointerId);
            sim.getState().pressInput(row.name);
          }}
          onPointerUp={release} onPointerCancel={release} data-testid="input-hold">
          Hold
        </button>
      </td>
      <FromCell field={field} machine={machine} forced={forced} />
    </tr>
  );
}

/** Where an input comes from when not from this panel: the device, or the machine (unless forced). */
function FromCell({ field, machine, forced }: { field: string | undefined; machine: string | undefined; forced: string | undefined }) {
  if (forced !== undefined) return null;
  if (field)
    return (
      <td>
        <span className="rs-sim-unit" data-testid="input-from-device">from the device</span>
      </td>
    );
  if (machine)
    return (
      <td>
        <span className="rs-sim-unit" title={machine} data-testid="input-from-machine">from the machine</span>
      </td>
    );
  return null;
}

function WordInput({ row }: { row: InputRow }) {
  const sim = useSimStore();
  const field = useFieldInput(row.name);
  const value = useSim((s) => liveText(s, row.name));
  const forced = useSim((s) => forcedText(s, row.name));
  const [text, setText] = useState('');
  const machine = field ? undefined : row.machine;
  const write = () => !field && !machine && text.trim() && sim.getState().write(row.name, { text });
  return (
    <tr data-testid={`input-${row.name}`}>
      <Label row={row} />
      <td>
        {value ?? '—'}
        {forced !== undefined && <ForcedBadge title={`forced to ${forced}`} />}
      </td>
      <td>
        <input className="rs-sim-text rs-sim-narrow" aria-label={`New value for ${row.name}`} placeholder={row.type} value={text}
          onChange={(e) => setText(e.target.value)} onKeyDown={(e) => e.key === 'Enter' && write()} />
        <button type="button" className="rs-sim-btn" disabled={value === undefined || field !== undefined || machine !== undefined}
          title={field ? fieldInputWords(field, row.name) : machine} onClick={write}>Set</button>
      </td>
      <FromCell field={undefined} machine={machine} forced={forced} />
    </tr>
  );
}
