// What a scenario run that ended on an error says (the Tests tab's run view).
import type { ScenarioResult } from '../../sim/scenario';

/**
 * A run that ended on an error: one that ran failed at its scan (a machine's consequence, "the tank
 * overflowed at scan 576 (57.50 s)", or a PLC fault, "scan 12: …"); one that ran no scan did not run
 * (it does not compile, a bad line). A consequence used to read "did not run" after 576 scans.
 */
export function errorText(result: ScenarioResult): string {
  const error = result.error ?? '';
  if (result.scans <= 0) return `did not run: ${error}`;
  const at = `scan ${result.scans.toLocaleString('en-US')}`;
  if (error.startsWith(`scan ${result.scans}: `))
    return `FAIL at ${at}: ${error.slice(`scan ${result.scans}: `.length)}`;
  // The error names its scan already (a consequence's text): said once.
  const named = [`scan ${result.scans}`, at].some((s) => new RegExp(`(^|\\D)${s}(\\D|$)`).test(error));
  return named ? `FAIL: ${error}` : `FAIL at ${at}: ${error}`;
}
