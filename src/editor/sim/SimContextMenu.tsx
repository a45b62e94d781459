// Right-click menu on a contact or coil while simulating: why?, force, unforce, watch, trend.
// The canvas opens it with simStore.openContextMenu({ x, y, variable }) (page coordinates).
// With hardware attached, a field input (a %I variable the gateway has as a point) comes from the
// device: the menu says so, and forcing it asks for a confirmation first, as stepping on hardware does.
import { useEffect, useRef, useState, type RefObject } from 'react';
import type { SimValueInput } from '../../sim/protocol';
import type { SimState } from '../../store/simState';
import { fieldInputAddress, fieldInputWords } from '../hardware/fieldIo';
import { useGateway } from '../hardware/useGateway';
import { showWhyTab } from '../history/useWhyKey';
import { forcedText, liveText } from './liveValues';
import { useDocumentStore } from '../../store/documentStore';
import { useSim, useSimStore } from './simContext';
import { openBody } from './useFollowExecution';
import './sim.css';

const selectMenu = (s: SimState) => s.contextMenu;

export function SimContextMenu() {
  const menu = useSim(selectMenu);
  if (menu?.call) return <CallMenu key={`${menu.call.instance}@${menu.x},${menu.y}`} x={menu.x} y={menu.y} call={menu.call} />;
  return menu ? <OpenMenu key={`${menu.variable}@${menu.x},${menu.y}`} x={menu.x} y={menu.y} variable={menu.variable} /> : null;
}

/** Closes the menu on a press outside it or Escape; focuses its first item. */
function useMenuDismiss(ref: RefObject<HTMLDivElement | null>): void {
  const sim = useSimStore();
  useEffect(() => {
    ref.current?.querySelector<HTMLElement>('[role="menuitem"]')?.focus();
    const onDown = (e: PointerEvent) => {
      if (!ref.current?.contains(e.target as Node)) sim.getState().closeContextMenu();
    };
    const onKey = (e: KeyboardEvent) => e.key === 'Escape' && sim.getState().closeContextMenu();
    window.addEventListener('pointerdown', onDown, true);
    window.addEventListener('keydown', onKey);
    return () => {
      window.removeEventListener('pointerdown', onDown, true);
      window.removeEventListener('keydown', onKey);
    };
  }, [sim, ref]);
}

/** A call of a user FB: open its body with this instance picked (as CODESYS's "Open instance"). */
function CallMenu({ x, y, call }: { x: number; y: number; call: { pou: string; instance: string } }) {
  const sim = useSimStore();
  const documents = useDocumentStore();
  const ref = useRef<HTMLDivElement>(null);
  useMenuDismiss(ref);
  return (
    <div ref={ref} className="rs-sim-menu" role="menu" aria-label={`Simulation: ${call.instance}`} style={{ left: x, top: y }} data-testid="sim-context-menu">
      <div className="rs-sim-menu-title">
        {call.instance} <span className="rs-sim-unit">({call.pou})</span>
      </div>
      <button type="button" role="menuitem" data-testid="sim-open-instance"
        onClick={() => {
          sim.getState().closeContextMenu();
          openBody(documents, sim, call.pou, call.instance);
        }}>
        Open instance {call.instance}
      </button>
      <button type="button" role="menuitem" data-testid="sim-watch-instance"
        onClick={() => {
          sim.getState().closeContextMenu();
          sim.getState().addWatch(call.instance);
        }}>
        Add {call.instance} to watch
      </button>
    </div>
  );
}

function OpenMenu({ x, y, variable }: { x: number; y: number; variable: string }) {
  const sim = useSimStore();
  const ref = useRef<HTMLDivElement>(null);
  const described = useSim((s) => s.layout?.variables[s.variableIndex.get(variable.toUpperCase()) ?? -1]);
  const type = described?.type;
  // The engine forces variables, not FB pins (a PLC forces I/O and memory, not block internals).
  const forceable = described !== undefined && described.role !== 'pin';
  const value = useSim((s) => liveText(s, variable));
  const forced = useSim((s) => forcedText(s, variable));
  const [text, setText] = useState('');
  const gateway = useGateway();
  const field = fieldInputAddress(described, gateway);
  /** A force of a field input waiting for the confirmation. */
  const [confirming, setConfirming] = useState<{ input: SimValueInput; words: string } | undefined>();
  const close = () => sim.getState().closeContextMenu();
  useMenuDismiss(ref);
  const act = (fn: () => void) => () => {
    fn();
    close();
  };
  const s = sim.getState();
  const force = (input: SimValueInput, words: string) => () => {
    if (field) setConfirming({ input, words });
    else act(() => s.force(variable, input))();
  };
  if (field && confirming) {
    return (
      <div ref={ref} className="rs-sim-menu" role="alertdialog" aria-label={`Force ${variable} on hardware?`} style={{ left: x, top: y }}
        data-testid="sim-context-menu">
        <div className="rs-sim-menu-title">Force {variable} {confirming.words}?</div>
        <div className="rs-sim-menu-row rs-sim-field-note" data-testid="sim-force-field-warning">
          The program will ignore the device&apos;s {field} and use {confirming.words}: outputs that depend on it are driven on the real
          hardware. The variable is marked forced until you unforce it.
        </div>
        <button type="button" role="menuitem" className="rs-sim-danger" onClick={act(() => s.force(variable, confirming.input))}
          data-testid="sim-force-confirm">
          Force and drive outputs
        </button>
        <button type="button" role="menuitem" onClick={close} data-testid="sim-force-cancel">Cancel</button>
      </div>
    );
  }
  return (
    <div ref={ref} className="rs-sim-menu" role="menu" aria-label={`Simulation: ${variable}`} style={{ left: x, top: y }} data-testid="sim-context-menu">
      <div className="rs-sim-menu-title">
        {variable} {value !== undefined && <span className="rs-sim-unit">= {value}</span>}
        {forced !== undefined && <span className="rs-sim-forced-tag"> forced {forced}</span>}
      </div>
      {field && (
        <div className="rs-sim-menu-row rs-sim-field-note" role="note" data-testid="sim-field-input">
          {fieldInputWords(field, variable)}
        </div>
      )}
      {!forceable ? (
        <div className="rs-sim-menu-row rs-sim-unit">Function block pins cannot be forced.</div>
      ) : type === 'BOOL' ? (
        <>
          <button type="button" role="menuitem" onClick={force({ value: true }, 'TRUE')}>Force TRUE</button>
          <button type="button" role="menuitem" onClick={force({ value: false }, 'FALSE')}>Force FALSE</button>
        </>
      ) : (
        <div className="rs-sim-menu-row">
          <input className="rs-sim-text rs-sim-narrow" aria-label={`Force ${variable} to`} placeholder={type ?? 'value'} value={text}
            onChange={(e) => setText(e.target.value)} onKeyDown={(e) => e.key === 'Enter' && text.trim() && force({ text }, text.trim())()} />
          <button type="button" role="menuitem" disabled={!text.trim()} onClick={force({ text }, text.trim())}>Force</button>
        </div>
      )}
      {forceable && (
        <button type="button" role="menuitem" disabled={forced === undefined} onClick={act(() => s.unforce(variable))}>Unforce</button>
      )}
      <button type="button" role="menuitem" onClick={act(() => s.unforceAll())}>Remove all forces</button>
      <button type="button" role="menuitem" data-testid="sim-why" aria-keyshortcuts="?"
        onClick={act(() => {
          s.explain({ kind: 'variable', name: variable });
          showWhyTab();
        })}>
        Why is {variable} {value ?? 'so'}?
      </button>
      <button type="button" role="menuitem" onClick={act(() => s.addWatch(variable))}>Add to watch</button>
      <button type="button" role="menuitem" onClick={act(() => s.toggleTrend(variable))}>
        {s.trendNames.some((n) => n.toUpperCase() === variable.toUpperCase()) ? 'Remove from trend' : 'Add to trend'}
      </button>
    </div>
  );
}
