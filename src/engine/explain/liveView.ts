// A ScanView of a PLC's last scan (no history): for the CLI's failure reports and for tests.
import type { Plc } from '../api';
import type { CompiledProgram } from '../compile/program';
import type { ScanView } from './view';
import { netOn } from './view';

export function liveScanView(plc: Plc, program: CompiledProgram): ScanView {
  const probe = plc.probe?.();
  if (!probe) throw new Error('this PLC cannot be explained (it has no probe)');
  const scan = plc.scanCount;
  return {
    scan,
    timeMs: plc.timeMs,
    value: (name) => {
      try {
        return plc.read(name);
      } catch {
        return undefined;
      }
    },
    executed: (n) => scan > 0 && probe.ranIn[n] === scan,
    net: (n, net) => netOn(program, probe.words, probe.power, scan > 0 && probe.ranIn[n] === scan, n, net),
  };
}
