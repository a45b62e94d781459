// "Why?": the explanation of a value at the viewed scan, in plain words, with "when did it change?"
// links that move the timeline there and explain again (follow the chain back).
import { useState } from 'react';
import type { SimState } from '../../store/simState';
import { useSim, useSimStore } from '../sim/simContext';
import './history.css';

const selectExplanation = (s: SimState) => s.explanation;
const selectMessage = (s: SimState) => s.historyMessage;

/** A line of the explanation as a list item: the list draws the bullet (the text's own "• " is for plain text). */
export function whyLineText(line: string): string {
  return line.trim().replace(/^[•\-*]\s+/, '');
}

export function WhyPanel() {
  const sim = useSimStore();
  const e = useSim(selectExplanation);
  const message = useSim(selectMessage);
  const [name, setName] = useState('');
  const s = sim.getState();
  const ask = () => name.trim() && s.explain({ kind: 'variable', name: name.trim() });
  return (
    <div className="rs-sim-panel rs-why" data-testid="why-panel">
      <div className="rs-sim-panel-bar">
        <input type="text" className="rs-timeline-input" placeholder="Variable, e.g. Motor" aria-label="Why is this variable what it is?"
          value={name} onChange={(ev) => setName(ev.target.value)} onKeyDown={(ev) => ev.key === 'Enter' && ask()} data-testid="why-input" />
        <button type="button" className="rs-sim-btn" onClick={ask} data-testid="why-ask">Why?</button>
        {e && <button type="button" className="rs-sim-btn" onClick={() => s.closeExplanation()}>Clear</button>}
      </div>
      {!e ? (
        <p className="rs-sim-empty">{message ?? 'Right-click a contact or coil while simulating and choose Why?, or type a variable above.'}</p>
      ) : (
        <div data-testid="why-explanation">
          <h3 className="rs-why-title">{e.title}</h3>
          <ul className="rs-why-lines">
            {e.lines.map((l, i) => (
              <li key={i} className={l.startsWith('  ') ? 'rs-why-sub' : undefined}>{whyLineText(l)}</li>
            ))}
          </ul>
          {e.links.length > 0 && (
            <ul className="rs-why-links">
              {e.links.map((l, i) => (
                <li key={i}>
                  <button type="button" className="rs-link-button" data-testid="why-link"
                    onClick={() => {
                      s.seekHistory(l.scan);
                      s.explain(l.target, l.scan);
                    }}>
                    {l.label} →
                  </button>
                </li>
              ))}
            </ul>
          )}
        </div>
      )}
    </div>
  );
}
