// The scan history timeline under the canvas: drag to any recorded scan and the canvas, the watch
// table and the trend show that scan exactly as it was, marked HISTORY, while the program runs on.
// Keys (on the timeline): ←/→ previous/next scan, Shift+←/→ previous/next change of the variable,
// Enter in the condition: next scan where it holds (Shift+Enter: previous). Live goes back.
import { useState } from 'react';
import type { SimState } from '../../store/simState';
import { useSim, useSimStore } from '../sim/simContext';
import { downloadText } from './download';
import { useWhyKey } from './useWhyKey';
import './history.css';

const selectHistory = (s: SimState) => s.history;
const selectScan = (s: SimState) => s.historyScan;
const selectTime = (s: SimState) => s.historyTimeMs;
const selectMessage = (s: SimState) => s.historyMessage;

export function Timeline() {
  const sim = useSimStore();
  const history = useSim(selectHistory);
  const scan = useSim(selectScan);
  const timeMs = useSim(selectTime);
  const message = useSim(selectMessage);
  const [variable, setVariable] = useState('');
  const [condition, setCondition] = useState('');
  useWhyKey(sim);
  if (!history) return null;
  const s = sim.getState();
  const at = scan ?? history.last;
  const stepTo = (delta: number) => s.seekHistory(at + delta);
  const change = (direction: 1 | -1) => variable.trim() && s.findChange(variable.trim(), direction);
  const find = (direction: 1 | -1) => condition.trim() && s.findCondition(condition.trim(), direction);
  const onKey = (e: React.KeyboardEvent) => {
    if (e.target instanceof HTMLInputElement && e.target.type === 'text') return;
    if (e.key === 'ArrowLeft' || e.key === 'ArrowRight') {
      const d = e.key === 'ArrowLeft' ? -1 : 1;
      e.preventDefault();
      if (e.shiftKey) change(d);
      else stepTo(d);
    }
  };
  return (
    <div className={`rs-timeline${scan !== undefined ? ' rs-timeline-history' : ''}`} data-testid="timeline" onKeyDown={onKey} role="group" aria-label="Scan history">
      <span className="rs-timeline-state" data-testid="history-marker"
        title={scan !== undefined ? `History: scan ${scan}` : `Live; scans ${history.first}–${history.last} recorded`}>
        {scan !== undefined ? (
          <>
            <strong>HISTORY</strong> scan {scan.toLocaleString('en-US')} · {(timeMs! / 1000).toFixed(3)} s
          </>
        ) : (
          <>Live · {history.first.toLocaleString('en-US')}–{history.last.toLocaleString('en-US')}</>
        )}
      </span>
      <button type="button" className="rs-sim-btn" aria-label="Previous scan" title="Previous scan (←)" onClick={() => stepTo(-1)} data-testid="history-prev">◀</button>
      <input
        type="range"
        className="rs-timeline-slider"
        min={history.first}
        max={history.last}
        value={at}
        aria-label="Recorded scan"
        data-testid="history-slider"
        onChange={(e) => s.seekHistory(Number(e.target.value))}
        onKeyDown={(e) => {
          // The slider moves by one scan itself; Shift+arrows jump to the variable's changes.
          if (e.shiftKey && (e.key === 'ArrowLeft' || e.key === 'ArrowRight')) {
            e.preventDefault();
            e.stopPropagation();
            change(e.key === 'ArrowLeft' ? -1 : 1);
          } else e.stopPropagation();
        }}
      />
      <button type="button" className="rs-sim-btn" aria-label="Next scan" title="Next scan (→)" onClick={() => stepTo(1)} data-testid="history-next">▶</button>
      <button type="button" className="rs-sim-btn" disabled={scan === undefined} onClick={() => s.goLive()} data-testid="history-live">Live</button>
      <span className="rs-timeline-group">
        <input type="text" className="rs-timeline-input" placeholder="Variable" aria-label="Variable to follow" value={variable}
          onChange={(e) => setVariable(e.target.value)} data-testid="history-variable" />
        <button type="button" className="rs-sim-btn" title="Previous change of the variable (Shift+←)" aria-label="Previous change" onClick={() => change(-1)} data-testid="history-prev-change">⇤</button>
        <button type="button" className="rs-sim-btn" title="Next change of the variable (Shift+→)" aria-label="Next change" onClick={() => change(1)} data-testid="history-next-change">⇥</button>
      </span>
      <span className="rs-timeline-group">
        <input type="text" className="rs-timeline-input rs-timeline-condition" placeholder="Condition, e.g. Motor AND NOT Start" title="Condition, e.g. Motor AND NOT Start" aria-label="Condition"
          value={condition} onChange={(e) => setCondition(e.target.value)} onKeyDown={(e) => e.key === 'Enter' && find(e.shiftKey ? -1 : 1)}
          data-testid="history-condition" />
        <button type="button" className="rs-sim-btn" onClick={() => find(1)} title="Next scan where the condition holds (Enter; Shift+Enter: previous)" data-testid="history-find">Find</button>
      </span>
      <button type="button" className="rs-sim-btn" title="Save the recorded scans as a trace CSV (rungsmith simulate format)"
        onClick={() => void s.exportHistory({ format: 'trace' }).then((text) => downloadText('trace.csv', text))} data-testid="history-export">
        Export
      </button>
      {message && <span className="rs-timeline-message" role="status" data-testid="history-message">{message}</span>}
    </div>
  );
}
