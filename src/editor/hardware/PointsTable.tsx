// The gateway's I/O points with live values and quality; switches for the simulated device's inputs.
import { useMemo, useState } from 'react';
import { gatewayLink } from '../../bridge/gatewayLink';
import { checkBindings } from '../../bridge/mapping';
import { POINT_RANGE, type PointInfo, type WireValue } from '../../protocol/points';
import { selectProject, useDocument } from '../../store/documentStore';
import { useGateway } from './useGateway';

export function PointsTable() {
  const view = useGateway();
  const project = useDocument(selectProject);
  const report = useMemo(() => checkBindings(project, view.points), [project, view.points]);
  const names = useMemo(() => {
    const m = new Map<string, string[]>();
    for (const b of report.bindings) m.set(b.address, [...(m.get(b.address) ?? []), b.variable]);
    return m;
  }, [report]);
  if (view.link !== 'open') return null;
  const simulated = new Set(view.devices.filter((d) => d.kind === 'simulated').map((d) => d.id));
  const manyDevices = view.devices.length > 1;
  // An output's value is what its device last acknowledged: with the device not online, what it
  // holds now is unknown (a cut cable leaves a coupler's outputs as they were), so it shows stale.
  const down = new Set((view.status?.devices ?? []).filter((d) => d.state !== 'online').map((d) => d.id));
  return (
    <section className="rs-hw-section" aria-label="I/O points">
      {report.problems.length > 0 && (
        <ul className="rs-hw-mapping" data-testid="hw-mapping" aria-label="I/O mapping problems">
          {report.problems.map((p, i) => (
            <li key={i} className={p.severity === 'error' ? 'rs-hw-error' : 'rs-hw-warning'}>
              <code>{p.rule}</code> {p.message}
            </li>
          ))}
        </ul>
      )}
      <table className="rs-hw-table" data-testid="hw-points">
        <thead>
          <tr>
            <th>Address</th>
            <th>Variable</th>
            <th>Type</th>
            {manyDevices && <th>Device</th>}
            <th>Value</th>
            <th>Quality</th>
          </tr>
        </thead>
        <tbody>
          {view.points.map((p) => (
            <PointRow key={p.address} point={p} value={view.values[p.address]} quality={p.dir === 'out' && down.has(p.device) ? 'stale' : view.quality[p.address]}
              variables={names.get(p.address)} settable={p.dir === 'in' && simulated.has(p.device)} showDevice={manyDevices} />
          ))}
        </tbody>
      </table>
    </section>
  );
}

interface RowProps {
  readonly point: PointInfo;
  readonly value: WireValue | undefined;
  readonly quality: string | undefined;
  readonly variables: readonly string[] | undefined;
  readonly settable: boolean;
  readonly showDevice: boolean;
}

function PointRow({ point, value, quality, variables, settable, showDevice }: RowProps) {
  return (
    <tr data-testid={`hw-point-${point.address}`} className={quality === 'stale' ? 'rs-hw-stale' : undefined}>
      <td>
        <code>{point.address}</code>
      </td>
      <td>{variables?.join(', ') ?? ''}</td>
      <td>{point.type}</td>
      {showDevice && <td>{point.device}</td>}
      <td>{settable ? <SimulatedInput point={point} value={value} /> : <span data-testid="hw-value">{showValue(value)}</span>}</td>
      <td className={`rs-hw-quality-${quality ?? 'none'}`}>{quality ?? '—'}</td>
    </tr>
  );
}

const showValue = (v: WireValue | undefined) => (v === undefined ? '—' : typeof v === 'boolean' ? (v ? 'TRUE' : 'FALSE') : String(v));

function SimulatedInput({ point, value }: { point: PointInfo; value: WireValue | undefined }) {
  const [draft, setDraft] = useState<string | null>(null);
  if (point.type === 'BOOL') {
    const on = value === true;
    return (
      <button type="button" role="switch" aria-checked={on} aria-label={`${point.address} simulated input`} data-testid="hw-switch"
        className={`rs-hw-switch${on ? ' rs-hw-on' : ''}`} onClick={() => gatewayLink.client?.simulate({ [point.address]: !on })}>
        {on ? 'TRUE' : 'FALSE'}
      </button>
    );
  }
  const { min, max } = POINT_RANGE[point.type];
  const text = draft ?? showValue(value);
  const n = Number(text);
  const valid = Number.isInteger(n) && n >= min && n <= max;
  const commit = () => {
    if (draft !== null && valid) gatewayLink.client?.simulate({ [point.address]: n });
    setDraft(null);
  };
  return (
    <input className="rs-hw-word" inputMode="numeric" aria-label={`${point.address} simulated input`} aria-invalid={!valid} value={text}
      title={valid ? `${min}..${max}` : `an integer ${min}..${max}`} data-testid="hw-word"
      onChange={(e) => setDraft(e.target.value)} onBlur={commit} onKeyDown={(e) => {
        if (e.key === 'Enter') commit();
        if (e.key === 'Escape') setDraft(null);
      }} />
  );
}
