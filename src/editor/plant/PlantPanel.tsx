// The Plant panel (issue 26): the machine the program controls, drawn and animated (Konva), with
// its operator controls on the drawing (buttons held while pressed, switches that toggle), its
// consequences located by scan, faults to set on purpose, the I/O map (addresses editable) and
// "Declare the machine's I/O". At a recorded scan (history) it shows the machine as it was then.
import { useLayoutEffect, useRef, useState, type ReactNode } from 'react';
import { Layer, Stage } from 'react-konva';
import { locationText, parseLocation, type Value } from '../../model/iecTypes';
import type { Project } from '../../model/project';
import { taskText } from '../../plant/exercises';
import { mappedPoints } from '../../plant/loop';
import { PLANTS, plantById } from '../../plant/machines';
import { senseRecord } from '../../plant/points';
import type { PlantModel, PlantPoint } from '../../plant/types';
import { declarePlan, rewireAddress } from '../../plant/wiring';
import type { DocumentState } from '../../store/documentStore';
import { useDocument, useDocumentStore } from '../../store/documentStore';
import type { SimState } from '../../store/simState';
import { useSim, useSimStore } from '../sim/simContext';
import { useHardwareAttached } from './PlantHost';
import { PLANT_DRAWINGS, type PlantDrawing } from './drawings';
import './plant.css';

const selectPlantConfig = (s: DocumentState) => s.project.plant;
const selectProject = (s: DocumentState) => s.project;
const canonical = (address: string | undefined): string | undefined => {
  const loc = address ? parseLocation(address) : undefined;
  return loc ? locationText(loc) : undefined;
};

/**
 * What the program has at each point's address, as the machine is wired: the variable declared
 * there (the point is wired to it), or nothing, with where a variable of the point's name is
 * declared instead (rewired in the map but not in the program, or the other way round).
 */
function wiring(
  project: Project,
  points: readonly PlantPoint[],
): Map<string, { wired?: string; elsewhere?: string }> {
  const byLocation = new Map<string, string>();
  const byName = new Map<string, string>();
  for (const v of [
    ...project.globals,
    ...project.pous.flatMap((p) => (p.kind === 'PROGRAM' ? p.variables : [])),
  ]) {
    const at = canonical(v.location);
    if (!at) continue;
    if (!byLocation.has(at)) byLocation.set(at, v.name);
    if (!byName.has(v.name.toUpperCase())) byName.set(v.name.toUpperCase(), at);
  }
  const out = new Map<string, { wired?: string; elsewhere?: string }>();
  for (const p of points) {
    const wired = byLocation.get(canonical(p.address) ?? '');
    const elsewhere = wired ? undefined : byName.get(p.name.toUpperCase());
    out.set(p.name, { ...(wired ? { wired } : {}), ...(elsewhere ? { elsewhere } : {}) });
  }
  return out;
}
const selectFrame = (s: SimState) => s.plant;
const selectAtScan = (s: SimState) => s.plantAtScan;
const selectHistoryScan = (s: SimState) => s.historyScan;
const selectHistoryTime = (s: SimState) => s.historyTimeMs;
const selectScan = (s: SimState) => s.scan;
const selectTime = (s: SimState) => s.timeMs;
const selectCycle = (s: SimState) => s.cycleMs;
const selectMode = (s: SimState) => s.mode;
const seconds = (ms: number) => `${(ms / 1000).toFixed(2)} s`;

export function PlantPanel() {
  const config = useDocument(selectPlantConfig);
  const doc = useDocumentStore();
  const model = config ? plantById(config.id) : undefined;
  return (
    <div className="rs-plant-panel" data-testid="plant-panel">
      <label className="rs-plant-choose">
        Machine{' '}
        <select
          data-testid="plant-choose"
          value={model?.id ?? ''}
          onChange={(e) =>
            doc
              .getState()
              .setPlant(
                e.target.value ? { id: e.target.value } : undefined,
                e.target.value ? `Choose the machine ${e.target.value}` : 'Choose no machine',
              )
          }
        >
          <option value="">None</option>
          {PLANTS.map((p) => (
            <option key={p.id} value={p.id}>
              {p.title}
            </option>
          ))}
        </select>
      </label>
      {config && !model && (
        <p className="rs-plant-error">
          The project names the machine "{config.id}", which this version does not have.
        </p>
      )}
      {/* Keyed by the machine: what the panel said of the machine before (a refused address, a
          Declare report, a fault box awaiting the worker) does not stay under another one. */}
      {model && <Machine key={model.id} model={model} map={config?.map ?? {}} />}
    </div>
  );
}

function Machine({ model, map }: { model: PlantModel; map: Readonly<Record<string, string>> }) {
  const hardware = useHardwareAttached();
  const frame = useSim(selectFrame);
  const atScan = useSim(selectAtScan);
  const historyScan = useSim(selectHistoryScan);
  const historyTime = useSim(selectHistoryTime);
  const simScan = useSim(selectScan);
  const simTime = useSim(selectTime);
  const cycleMs = useSim(selectCycle);
  const mode = useSim(selectMode);
  /** When scan `scan` started, the machine having reached `endMs` after it. */
  const started = (scan: number, endMs: number, known: number | undefined, knownMs: number | undefined) =>
    scan === known && knownMs !== undefined ? knownMs : Math.max(0, endMs - cycleMs);
  const points = mappedPoints(model, map);
  const live = frame?.id === model.id ? frame : undefined;
  const shown = historyScan !== undefined && atScan ? atScan : live?.now;
  const state = shown?.state ?? model.initial();
  // The sensors as the program read them after that step: a stuck switch is drawn as it reads.
  const sensed = senseRecord(model, state, new Set(shown?.faults ?? []));
  const status =
    historyScan !== undefined
      ? atScan
        ? // A scan's time is when it started, as the History, the toolbar and the consequences
          // ("at scan 625 (12.48 s)") give it; the machine's own time is the scan's end.
          `Recorded scan ${atScan.scan.toLocaleString('en-US')} (${seconds(started(atScan.scan, atScan.timeMs, historyScan, historyTime))})`
        : live && historyScan <= live.since
          ? `Scan ${historyScan.toLocaleString('en-US')} came before this machine drove the program (chosen or rewired after scan ${live.since.toLocaleString('en-US')})`
          : `Scan ${historyScan.toLocaleString('en-US')} is no longer kept for the machine`
      : shown && shown.scan > 0
        ? `After scan ${shown.scan.toLocaleString('en-US')} (${seconds(started(shown.scan, shown.timeMs, simScan, simTime))})`
        : shown && mode !== 'stopped'
          ? // Attached to a program already past scan 0: the machine's first step is the next scan's.
            'Initial state: it moves from the next scan on'
          : 'Initial state: run or step the program';
  const drawing = PLANT_DRAWINGS[model.id];
  if (hardware)
    return (
      <p className="rs-plant-status" data-testid="plant-status">
        Set aside while this page drives the hardware: the program&apos;s inputs come from the device, not from the
        machine. Disconnect in the Hardware panel to run against the machine again.
      </p>
    );
  return (
    <>
      <p className="rs-plant-status" data-testid="plant-status" title={status}>
        {status}
      </p>
      {drawing && (
        <FittedDrawing drawing={drawing} state={state} sensed={sensed}>
          <OperatorControls
            points={points}
            held={shown?.operator ?? {}}
            live={live?.now.operator ?? {}}
            viewing={historyScan !== undefined}
          />
        </FittedDrawing>
      )}
      <Readouts model={model} state={state} />
      <Consequences />
      <Faults
        model={model}
        active={live?.now.faults ?? []}
        shown={historyScan !== undefined && atScan ? atScan.faults : undefined}
      />
      <IoMap model={model} map={map} points={points} />
      <details className="rs-plant-task">
        <summary>Task</summary>
        <pre data-testid="plant-task">{taskText(model, map)}</pre>
      </details>
    </>
  );
}

/** The drawing at most this much larger than drawn, when the panel is widened. */
const MAX_SCALE = 1.75;
/** ...and never smaller than this (the panel scrolls sideways instead). */
const MIN_SCALE = 0.6;

/**
 * The machine's drawing scaled to the panel's width (narrower panels shrink it rather than cut
 * it off; a widened panel enlarges it), with the operator controls placed over it.
 */
function FittedDrawing({
  drawing,
  state,
  sensed,
  children,
}: {
  drawing: PlantDrawing;
  state: unknown;
  sensed: Readonly<Record<string, Value>>;
  children: ReactNode;
}) {
  const outer = useRef<HTMLDivElement>(null);
  const [available, setAvailable] = useState(drawing.width);
  useLayoutEffect(() => {
    const el = outer.current;
    if (!el) return;
    const fit = () => setAvailable(el.clientWidth);
    fit();
    const resize = new ResizeObserver(fit);
    resize.observe(el);
    return () => resize.disconnect();
  }, []);
  // The border takes 2 px of the width.
  const scale = Math.min(MAX_SCALE, Math.max(MIN_SCALE, (available - 2) / drawing.width));
  const width = Math.floor(drawing.width * scale);
  const height = Math.floor(drawing.height * scale);
  const Drawing = drawing.component;
  return (
    <div ref={outer} className="rs-plant-fit">
      <div className="rs-plant-drawing" style={{ width, height }} data-scale={scale.toFixed(3)}>
        <Stage width={width} height={height} scaleX={scale} scaleY={scale}>
          <Layer listening={false}>
            <Drawing state={state} sensed={sensed} />
          </Layer>
        </Stage>
        {children}
      </div>
    </div>
  );
}

/**
 * Operator controls on the drawing: real buttons (keyboard, screen readers), placed over it. They
 * show the controls as the drawing's scan had them (`held`) but act on the live machine (`live`):
 * a switch turns from where it is now, and a control used at a recorded scan goes back to Live,
 * where what it does is seen.
 */
function OperatorControls({
  points,
  held,
  live,
  viewing,
}: {
  points: readonly PlantPoint[];
  held: Readonly<Record<string, boolean>>;
  live: Readonly<Record<string, boolean>>;
  viewing: boolean;
}) {
  const sim = useSimStore();
  const operators = points.filter((p) => p.kind === 'operator');
  const set = (name: string, value: boolean) => {
    if (viewing) sim.getState().goLive();
    sim.getState().plantOperator(name, value);
  };
  return (
    <div className="rs-plant-operator">
      {operators.map((p) =>
        p.control === 'switch' ? (
          <button
            key={p.name}
            type="button"
            data-testid={`plant-op-${p.name}`}
            aria-pressed={held[p.name] === true}
            title={p.comment}
            className={held[p.name] ? 'rs-plant-op on' : 'rs-plant-op'}
            onClick={() => set(p.name, !live[p.name])}
          >
            {p.name}
          </button>
        ) : (
          <button
            key={p.name}
            type="button"
            data-testid={`plant-op-${p.name}`}
            aria-pressed={held[p.name] === true}
            title={`${p.comment}: held while pressed`}
            className={held[p.name] ? 'rs-plant-op on' : 'rs-plant-op'}
            onPointerDown={(e) => {
              e.currentTarget.setPointerCapture?.(e.pointerId);
              set(p.name, true);
            }}
            onPointerUp={() => set(p.name, false)}
            onPointerCancel={() => set(p.name, false)}
            onKeyDown={(e) => {
              if ((e.key === ' ' || e.key === 'Enter') && !e.repeat) set(p.name, true);
            }}
            onKeyUp={(e) => {
              if (e.key === ' ' || e.key === 'Enter') set(p.name, false);
            }}
            // A push button springs back: held from the keyboard, it is released when the focus
            // leaves it (Tab, a click elsewhere), whose key-up then goes elsewhere.
            onBlur={() => {
              if (live[p.name]) sim.getState().plantOperator(p.name, false);
            }}
          >
            {p.name}
          </button>
        ),
      )}
    </div>
  );
}

function Readouts({ model, state }: { model: PlantModel; state: unknown }) {
  return (
    <table className="rs-plant-readouts" data-testid="plant-readouts">
      <tbody>
        {model.quantities.map((q) => {
          const v = model.quantity(state, q.name);
          const text =
            typeof v === 'boolean' ? (v ? 'yes' : 'no') : q.type === 'INT' ? String(v) : v.toFixed(1);
          return (
            <tr key={q.name} title={q.comment} data-testid={`plant-q-${q.name}`}>
              <th>{`${model.id}.${q.name}`}</th>
              <td>
                {text}
                {q.unit ? ` ${q.unit}` : ''}
              </td>
            </tr>
          );
        })}
      </tbody>
    </table>
  );
}

const selectHistory = (s: SimState) => s.history;

function Consequences() {
  const frame = useSim(selectFrame);
  const history = useSim(selectHistory);
  const sim = useSimStore();
  const events = frame?.events ?? [];
  // A consequence whose scan the history no longer keeps (a long run): said, instead of showing
  // the nearest scan kept as if it were that one.
  const [gone, setGone] = useState<string | undefined>();
  const show = (scan: number) => {
    const h = sim.getState().history;
    if (h && (scan < h.first || scan > h.last)) {
      setGone(
        `Scan ${scan.toLocaleString('en-US')} is no longer in the history (it keeps scans ${h.first.toLocaleString('en-US')} to ${h.last.toLocaleString('en-US')}).`,
      );
      return;
    }
    setGone(undefined);
    sim.getState().seekHistory(scan);
  };
  return (
    <div className="rs-plant-events" data-testid="plant-events">
      <h4>
        Consequences
        {frame && frame.eventCount > events.length ? ` (newest ${events.length} of ${frame.eventCount})` : ''}
      </h4>
      {events.length === 0 ? (
        <p className="rs-plant-empty">None so far.</p>
      ) : (
        <ul>
          {events.map((e, i) => (
            <li
              key={`${e.scan}-${e.id}-${i}`}
              className={e.severity === 'error' ? 'rs-plant-error' : 'rs-plant-warning'}
            >
              <button
                type="button"
                className="rs-plant-link"
                title={
                  history && e.scan < history.first
                    ? 'This scan is no longer in the history'
                    : 'Show this scan in the history'
                }
                onClick={() => show(e.scan)}
              >
                {e.text}
              </button>
            </li>
          ))}
        </ul>
      )}
      {gone && events.length > 0 && (
        <p className="rs-plant-warning" role="status" data-testid="plant-events-gone">
          {gone}
        </p>
      )}
    </div>
  );
}

/**
 * The fault boxes: the live machine's faults, or at a recorded scan the faults set in that scan
 * (`shown`, as the drawing shows it then). A box acts on the live machine, from its live faults,
 * and goes back to Live, as the operator controls do.
 */
function Faults({ model, active, shown }: { model: PlantModel; active: readonly string[]; shown: readonly string[] | undefined }) {
  const sim = useSimStore();
  // A box shows what was asked until the worker's next frame says what is set.
  const [asked, setAsked] = useState<
    { readonly id: string; readonly on: boolean; readonly against: string } | undefined
  >();
  const key = active.join(',');
  const pending = asked && asked.against === key ? asked : undefined;
  return (
    <fieldset className="rs-plant-faults" data-testid="plant-faults">
      <legend>Faults</legend>
      {model.faults.map((f) => (
        <label key={f.id}>
          <input
            type="checkbox"
            data-testid={`plant-fault-${f.id}`}
            checked={pending?.id === f.id ? pending.on : (shown ?? active).includes(f.id)}
            onChange={(e) => {
              // At a recorded scan the box turns the live fault over (set if it is not now, cleared if it is).
              const on = shown ? !active.includes(f.id) : e.target.checked;
              if (shown) sim.getState().goLive();
              setAsked({ id: f.id, on, against: key });
              // A switch is stuck ON or stuck OFF, not both: setting one clears the other.
              const other = /_stuck_on$/.test(f.id)
                ? f.id.replace(/_on$/, '_off')
                : /_stuck_off$/.test(f.id)
                  ? f.id.replace(/_off$/, '_on')
                  : undefined;
              if (on && other && active.includes(other)) sim.getState().plantFault(other, false);
              sim.getState().plantFault(f.id, on);
            }}
          />{' '}
          {f.title}
        </label>
      ))}
    </fieldset>
  );
}

function IoMap({
  model,
  map,
  points,
}: {
  model: PlantModel;
  map: Readonly<Record<string, string>>;
  points: readonly PlantPoint[];
}) {
  const doc = useDocumentStore();
  const project = useDocument(selectProject);
  const wired = wiring(project, points);
  const [problem, setProblem] = useState<string | undefined>();
  const [declared, setDeclared] = useState<string | undefined>();
  const change = (point: PlantPoint, text: string) => {
    if (text.trim() === point.address) return;
    const typed = rewireAddress(points, point, text);
    if (typed.problem !== undefined) {
      setProblem(typed.problem);
      return;
    }
    const address = typed.address;
    setProblem(undefined);
    if (address === point.address) return;
    const original = model.points.find((q) => q.name === point.name)!;
    const next: Record<string, string> = { ...map };
    if (address === original.address) delete next[point.name];
    else next[point.name] = address;
    doc
      .getState()
      .setPlant(
        { id: model.id, ...(Object.keys(next).length ? { map: next } : {}) },
        `Change the address of ${point.name}`,
      );
  };
  const declare = () => {
    const s = doc.getState();
    const project = s.project;
    const runs = project.tasks.flatMap((t) => t.programs.map((p) => p.pou.toUpperCase()));
    const pou =
      project.pous.find((p) => p.kind === 'PROGRAM' && runs.includes(p.name.toUpperCase())) ??
      project.pous.find((p) => p.kind === 'PROGRAM');
    if (!pou) {
      setDeclared('The project has no PROGRAM to declare the I/O in.');
      return;
    }
    // A point rewired in the map whose variable (same name and type) is still at its old address
    // moves with it, in the same undo step as the variables added; a variable of a point's name
    // that cannot carry it (another type, no address, a global) is left alone and said.
    const plan = declarePlan(model, map, pou.variables, project.globals);
    const added = s.batch("Declare the machine's I/O", () => {
      const names = s.addVariables(plan.add, "Declare the machine's I/O", pou.id);
      for (const m of plan.moves) s.updateVariable(m.name, { location: m.to }, pou.id);
      return names;
    });
    const said = [
      added.length
        ? `Declared ${added.length} variable${added.length === 1 ? '' : 's'} in ${pou.name}: ${added.join(', ')}.`
        : '',
      plan.moves.length ? `Moved ${plan.moves.map((m) => `${m.name} from ${m.from} to ${m.to}`).join(', ')}.` : '',
      plan.kept.length ? `Not wired, left as declared: ${plan.kept.join(', ')}.` : '',
    ].filter(Boolean);
    setDeclared(said.length ? said.join(' ') : `Every point is declared in ${pou.name} already.`);
  };
  return (
    <div className="rs-plant-io">
      <h4>
        I/O map{' '}
        <button type="button" data-testid="plant-declare" onClick={declare}>
          Declare the machine's I/O
        </button>
      </h4>
      {declared && <p data-testid="plant-declared">{declared}</p>}
      {problem && (
        <p className="rs-plant-error" role="alert" data-testid="plant-io-problem">
          {problem}
        </p>
      )}
      <table data-testid="plant-io">
        <thead>
          <tr>
            <th>Address</th>
            <th>Point</th>
            <th title="The program's variable at the point's address: what the machine is wired to">
              In the program
            </th>
          </tr>
        </thead>
        <tbody>
          {points.map((p) => (
            <tr key={p.name}>
              <td>
                <input
                  key={p.address}
                  type="text"
                  size={7}
                  defaultValue={p.address}
                  aria-label={`Address of ${p.name}`}
                  data-testid={`plant-address-${p.name}`}
                  onBlur={(e) => change(p, e.target.value)}
                  onKeyDown={(e) => {
                    if (e.key === 'Enter') change(p, e.currentTarget.value);
                  }}
                />
              </td>
              <td>
                <span className="rs-plant-point">{p.name}</span>{' '}
                <span className="rs-plant-kind">
                  {p.type} {p.kind}
                </span>
                <div className="rs-plant-comment">{p.comment}</div>
              </td>
              <WiredCell point={p} at={wired.get(p.name) ?? {}} />
            </tr>
          ))}
        </tbody>
      </table>
    </div>
  );
}

function WiredCell({ point, at }: { point: PlantPoint; at: { wired?: string; elsewhere?: string } }) {
  if (at.wired) return <td data-testid={`plant-wired-${point.name}`}>{at.wired}</td>;
  return (
    <td
      data-testid={`plant-wired-${point.name}`}
      className={at.elsewhere ? 'rs-plant-warning' : 'rs-plant-empty'}
      title={
        at.elsewhere
          ? `The program declares ${point.name} at ${at.elsewhere}, the machine's ${point.name} is at ${point.address}: they are not connected`
          : `No variable of the program is at ${point.address}`
      }
    >
      {at.elsewhere ? `not wired: ${point.name} is at ${at.elsewhere}` : 'not wired'}
    </td>
  );
}
