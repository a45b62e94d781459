// Watch table: chosen variables with live values; write a value once, force or unforce it, trend it.
// A structure or array (or FB instance) is a tree row whose members expand below it (collapsed at
// first), each watchable, writable and forceable by its path (`P.X`, `A[2]`); an enumeration shows
// and is written by value name.
import { useMemo, useState } from 'react';
import { useStore } from 'zustand';
import { selectProject, useDocument } from '../../store/documentStore';
import type { SimVariable } from '../../sim/protocol';
import type { SimState } from '../../store/simState';
import { useDeviceMark } from '../hardware/deviceMarks';
import { fieldInputAddress, fieldInputWords } from '../hardware/fieldIo';
import { useGateway } from '../hardware/useGateway';
import { forcedText, liveText } from './liveValues';
import { useSim, useSimStore } from './simContext';
import { ForcedBadge } from '../theme/ForcedBadge';
import { useConfigurationInstances, useWatchCandidates } from './useWatchCandidates';
import { VariablePicker } from './VariablePicker';
import { preparedValues } from './preparedValues';
import { aggregateCandidates, enumText, leafCount, modelLeaf, watchTree, type WatchNode } from './watchTree';
import { otherPlantNameInfo, plantNameInfo, plantWatchText, usePlantCandidates } from '../plant/plantWatch';
import type { PlantName } from '../../plant/values';
import './sim.css';

const selectWatch = (s: SimState) => s.watch;
const selectForcedCount = (s: SimState) => s.forced.size;

export function WatchPanel() {
  const sim = useSimStore();
  const watch = useSim(selectWatch);
  const forcedCount = useSim(selectForcedCount);
  const readable = useWatchCandidates();
  const instances = useConfigurationInstances();
  const project = useDocument(selectProject);
  const machine = usePlantCandidates();
  // Readable names, then the struct/array variables (watched as trees of their members), then the machine's (`tank.level`).
  const candidates = useMemo(() => [...readable, ...aggregateCandidates(project, readable), ...machine], [readable, project, machine]);
  const add = (text: string) => {
    const name = text.trim();
    if (!name) return;
    // Spelt exactly first: `tank.Pump` (the contactor) is not `tank.pump` (its speed).
    const known = candidates.find((c) => c.name === name) ?? candidates.find((c) => c.name.toUpperCase() === name.toUpperCase());
    sim.getState().addWatch(known?.name ?? name);
  };
  return (
    <div className="rs-sim-panel" data-testid="watch-panel">
      <div className="rs-sim-panel-bar">
        <VariablePicker testId="watch" placeholder="Variable or Instance.PIN" label="Variable to watch" buttonLabel="Add to watch"
          candidates={candidates} instances={instances} describe={(c) => `${c.type}${c.location ? ` ${c.location}` : ''}`} onAdd={add} />
        <button type="button" className="rs-sim-btn" disabled={forcedCount === 0} onClick={() => sim.getState().unforceAll()}
          title="Remove every force" data-testid="unforce-all">
          Remove all forces{forcedCount > 0 ? ` (${forcedCount})` : ''}
        </button>
      </div>
      {watch.length === 0 ? (
        <p className="rs-sim-empty">No variables watched. Add one above, or right-click a contact or coil on the canvas while simulating.</p>
      ) : (
        <table className="rs-sim-table" aria-label="Watch">
          <thead>
            <tr><th>Variable</th><th>Type</th><th>Value</th><th title="A value typed here waits: Ctrl+F7 writes all prepared values once, F7 forces them">Prepared value</th><th /></tr>
          </thead>
          <tbody>
            {watch.map((name) => {
              const variable = readable.find((c) => c.name.toUpperCase() === name.toUpperCase());
              const members = variable ? [] : watchTree(name, readable);
              const onMachine = variable || members.length > 0 ? undefined : plantNameInfo(project, name);
              if (onMachine) return <PlantWatchRow key={name} name={name} info={onMachine} />;
              const elsewhere = variable || members.length > 0 ? undefined : otherPlantNameInfo(project, name);
              if (elsewhere)
                return <DetachedPlantRow key={name} name={name} other={elsewhere} current={project.plant?.id} />;
              return members.length > 0 ? (
                <WatchGroup key={name} node={{ path: name, label: name, children: members }} depth={0}
                  type={candidates.find((c) => c.name.toUpperCase() === name.toUpperCase())?.type} />
              ) : (
                <WatchRow key={name} name={name} variable={variable} />
              );
            })}
          </tbody>
        </table>
      )}
    </div>
  );
}

/**
 * A name of the machine (`tank.level`, `tank.Pump`): its value live or at the recorded scan viewed,
 * trendable; the machine works it out, so it is neither written nor forced here (operate the
 * machine's controls, set its faults, in the Plant panel).
 */
function PlantWatchRow({ name, info }: { name: string; info: PlantName }) {
  const sim = useSimStore();
  const value = useSim((s) => plantWatchText(s, name));
  const inTrend = useSim((s) => s.trendNames.includes(name));
  return (
    <tr data-testid={`watch-row-${name}`} className="rs-watch-machine">
      <td title={`${info.comment} (the machine's ${info.kind === 'quantity' ? 'quantity' : info.kind})`}>{name}</td>
      <td>{info.type}</td>
      <td data-testid="watch-value">{value ?? '—'}</td>
      <td className="rs-sim-unit">machine</td>
      <td className="rs-sim-actions">
        <label className="rs-sim-check" title="Show in the trend">
          <input type="checkbox" checked={inTrend} onChange={() => sim.getState().toggleTrend(name)} /> Trend
        </label>
        <button type="button" className="rs-sim-icon" aria-label={`Stop watching ${name}`} onClick={() => sim.getState().removeWatch(name)}>×</button>
      </td>
    </tr>
  );
}

/**
 * A name of a machine the project does not have now (`tank.level` watched, then the garage chosen):
 * said so, with nothing to write or force (it offered Write and Force, which answered
 * "unknown variable"); it reads again when that machine is chosen.
 */
function DetachedPlantRow({
  name,
  other,
  current,
}: {
  name: string;
  other: { readonly machine: string; readonly title: string; readonly info: PlantName };
  current: string | undefined;
}) {
  const sim = useSimStore();
  const why = `The machine ${other.machine} (${other.title}) is not chosen${current ? `: the project's machine is ${current}` : ''}; choose it in the Plant panel to read ${name}.`;
  return (
    <tr data-testid={`watch-row-${name}`} className="rs-watch-machine">
      <td title={why}>{name}</td>
      <td>{other.info.type}</td>
      <td data-testid="watch-value">—</td>
      <td className="rs-sim-unit" data-testid="watch-detached" title={why}>
        {other.machine} not chosen
      </td>
      <td className="rs-sim-actions">
        <button type="button" className="rs-sim-icon" aria-label={`Stop watching ${name}`} onClick={() => sim.getState().removeWatch(name)}>×</button>
      </td>
    </tr>
  );
}

/** A structure, array or instance row: ▸ expands its members (groups nest); × stops watching a top row. */
function WatchGroup({ node, depth, type }: { node: WatchNode; depth: number; type?: string | undefined }) {
  const sim = useSimStore();
  const [open, setOpen] = useState(false);
  const count = leafCount(node.children);
  return (
    <>
      <tr data-testid={`watch-row-${node.path}`} className="rs-watch-group">
        <td style={{ paddingLeft: `${depth * 14 + 2}px` }}>
          <button type="button" className="rs-sim-icon rs-watch-toggle" aria-expanded={open}
            aria-label={`${open ? 'Collapse' : 'Expand'} ${node.path}`} data-testid="watch-expand" onClick={() => setOpen(!open)}>
            {open ? '▾' : '▸'}
          </button>{' '}
          {node.label}
        </td>
        <td>{type ?? ''}</td>
        <td colSpan={2}>{count} value{count === 1 ? '' : 's'}</td>
        <td className="rs-sim-actions">
          {depth === 0 && (
            <button type="button" className="rs-sim-icon" aria-label={`Stop watching ${node.path}`}
              onClick={() => sim.getState().removeWatch(node.path)}>×</button>
          )}
        </td>
      </tr>
      {open &&
        node.children.map((child) =>
          child.leaf ? (
            <WatchRow key={child.path} name={child.path} variable={child.leaf} depth={depth + 1} label={child.label} />
          ) : (
            <WatchGroup key={child.path} node={child} depth={depth + 1} />
          ),
        )}
    </>
  );
}

function WatchRow({ name, variable, depth = 0, label }: { name: string; variable: SimVariable | undefined; depth?: number; label?: string }) {
  const project = useDocument(selectProject);
  const leaf = modelLeaf(project, name);
  const enumValues = leaf?.enumValues;
  const type = leaf && leaf.typeName.toUpperCase() !== leaf.type ? leaf.typeName : (variable?.type ?? '?');
  const pin = variable?.role === 'pin';
  const sim = useSimStore();
  const value = enumText(leaf, useSim((s) => liveText(s, name)));
  const forced = enumText(leaf, useSim((s) => forcedText(s, name)));
  const inTrend = useSim((s) => s.trendNames.some((n) => n.toUpperCase() === name.toUpperCase()));
  const device = useDeviceMark(name);
  // With hardware attached a field input comes from the device: no one-off write, only a confirmed force.
  const field = fieldInputAddress(variable, useGateway());
  const [confirmForce, setConfirmForce] = useState(false);
  // The prepared value (preparedValues.ts): Ctrl+F7 / F7 write or force every prepared value.
  const text = useStore(preparedValues, (s) => s.values.get(name.toUpperCase())?.text ?? '');
  const inputOf = (typed: string) => {
    // An enumeration value is stored as its index.
    const index = enumValues?.findIndex((v) => v.toUpperCase() === typed.trim().toUpperCase()) ?? -1;
    if (index >= 0) return { value: index };
    return { text: typed.trim() || (type === 'BOOL' ? (value === 'TRUE' ? 'FALSE' : 'TRUE') : '') };
  };
  const input = () => inputOf(text);
  const setText = (typed: string) => preparedValues.getState().prepare({ name, text: typed, input: inputOf(typed), field, pin });
  return (
    <tr data-testid={`watch-row-${name}`}>
      <td style={depth > 0 ? { paddingLeft: `${depth * 14 + 18}px` } : undefined} title={name}>{label ?? name}</td>
      <td>{type}</td>
      <td className={forced !== undefined ? 'rs-sim-forced' : undefined} data-testid="watch-value"
        title={forced !== undefined ? `forced to ${forced}` : undefined}>
        {value ?? '—'}
        {forced !== undefined && <ForcedBadge title={`forced to ${forced}`} />}
        {device !== undefined && (
          <span className="rs-sim-device-tag" data-testid="watch-device" title="The value the device holds now">
            {' '}
            {device}
          </span>
        )}
      </td>
      <td>
{enumValues ? (
          <select className="rs-sim-text rs-sim-narrow" aria-label={`New value for ${name}`} value={text}
            onChange={(e) => setText(e.target.value)} data-testid="watch-input">
            <option value="">(value)</option>
            {enumValues.map((v) => <option key={v} value={v}>{v}</option>)}
          </select>
        ) : (
                <input className="rs-sim-text rs-sim-narrow" aria-label={`New value for ${name}`} value={text}
          placeholder={type === 'BOOL' ? 'TRUE/FALSE' : type} onChange={(e) => setText(e.target.value)}
          onKeyDown={(e) => e.key === 'Enter' && !field && sim.getState().write(name, input())} data-testid="watch-input" />
        )}
      </td>
      <td className="rs-sim-actions">
        <button type="button" className="rs-sim-btn" disabled={field !== undefined}
          title={field ? fieldInputWords(field, name) : 'Write the value once (an input: at the next input read)'}
          onClick={() => sim.getState().write(name, input())} data-testid="watch-write">Write</button>
        {field && confirmForce ? (
          <>
            <button type="button" className="rs-sim-btn rs-sim-danger" data-testid="watch-force-confirm"
              title={`The program ignores the device's ${field}; outputs that depend on it are driven on the hardware`}
              onClick={() => {
                setConfirmForce(false);
                sim.getState().force(name, input());
              }}>
              Force on hardware
            </button>
            <button type="button" className="rs-sim-btn" onClick={() => setConfirmForce(false)}>Cancel</button>
          </>
        ) : (
          <button type="button" className="rs-sim-btn" disabled={pin}
            title={pin ? 'Function block pins cannot be forced' : 'Force: the variable keeps this value whatever the program or inputs do'}
            onClick={() => (field ? setConfirmForce(true) : sim.getState().force(name, input()))} data-testid="watch-force">Force</button>
        )}
        <button type="button" className="rs-sim-btn" disabled={forced === undefined}
          onClick={() => sim.getState().unforce(name)} data-testid="watch-unforce">Unforce</button>
        <label className="rs-sim-check" title="Show in the trend">
          <input type="checkbox" checked={inTrend} onChange={() => sim.getState().toggleTrend(name)} /> Trend
        </label>
        <button type="button" className="rs-sim-icon" aria-label={`Stop watching ${name}`} onClick={() => sim.getState().removeWatch(name)}>×</button>
      </td>
    </tr>
  );
}
