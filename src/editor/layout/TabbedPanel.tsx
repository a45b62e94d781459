// A panel with tabs (WAI-ARIA tabs pattern): the right side panel and the bottom panel.
import { useState, type KeyboardEvent } from 'react';
import type { PanelSlot } from './panels';

export function TabbedPanel({
  panels,
  label,
  className,
  onActivate,
}: {
  readonly panels: readonly PanelSlot[];
  readonly label: string;
  readonly className: string;
  /** Called when a tab is chosen (a click, the keyboard, or code clicking the tab). */
  readonly onActivate?: () => void;
}) {
  const [active, setChosen] = useState(panels[0]?.id ?? '');
  const setActive = (id: string) => {
    setChosen(id);
    onActivate?.();
  };
  const current = panels.find((p) => p.id === active) ?? panels[0];
  const onKeyDown = (e: KeyboardEvent) => {
    if (e.key !== 'ArrowLeft' && e.key !== 'ArrowRight') return;
    e.preventDefault();
    const i = panels.findIndex((p) => p.id === current?.id);
    const next = panels[(i + (e.key === 'ArrowRight' ? 1 : -1) + panels.length) % panels.length];
    if (next) {
      setActive(next.id);
      document.getElementById(`rs-tab-${next.id}`)?.focus();
    }
  };
  return (
    <section className={`rs-tabbed ${className}`} aria-label={label}>
      <div role="tablist" aria-label={label} className="rs-tablist" onKeyDown={onKeyDown}>
        {panels.map((p) => (
          <button
            key={p.id}
            id={`rs-tab-${p.id}`}
            role="tab"
            type="button"
            aria-selected={p.id === current?.id}
            aria-controls={`rs-tabpanel-${p.id}`}
            tabIndex={p.id === current?.id ? 0 : -1}
            data-testid={`tab-${p.id}`}
            className="rs-tab"
            onClick={() => setActive(p.id)}
          >
            {p.title}
          </button>
        ))}
      </div>
      {current && (
        // Only the open tab is mounted: a hidden panel costs nothing on big projects.
        <div
          id={`rs-tabpanel-${current.id}`}
          role="tabpanel"
          aria-labelledby={`rs-tab-${current.id}`}
          className="rs-tabpanel"
        >
          <current.component />
        </div>
      )}
    </section>
  );
}
