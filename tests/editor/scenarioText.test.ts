// The Tests tab's words for a scenario run that ended on an error: one that ran failed at its scan,
// one that ran no scan did not run.
import { describe, expect, it } from 'vitest';
import { errorText } from '../../src/editor/scenarios/scenarioText';

const result = (scans: number, error: string) => ({ name: 'S', ok: false, scans, divergences: [], error });

describe('errorText', () => {
  it("a machine's consequence after scans ran is a failure at its scan, said once", () => {
    expect(errorText(result(576, 'the tank overflowed at scan 576 (57.50 s)'))).toBe(
      'FAIL: the tank overflowed at scan 576 (57.50 s)',
    );
    expect(errorText(result(1204, 'the tank overflowed at scan 1,204 (120.30 s)'))).toBe(
      'FAIL: the tank overflowed at scan 1,204 (120.30 s)',
    );
  });
  it('a PLC fault at a scan is a failure at that scan', () => {
    expect(errorText(result(12, 'scan 12: division by zero in Main network 3'))).toBe(
      'FAIL at scan 12: division by zero in Main network 3',
    );
  });
  it('an error naming no scan after scans ran says where it stopped', () => {
    expect(errorText(result(3, 'the machine stopped answering'))).toBe(
      'FAIL at scan 3: the machine stopped answering',
    );
  });
  it('no scan run: it did not run', () => {
    expect(errorText(result(0, 'the program does not compile; see the Problems panel'))).toBe(
      'did not run: the program does not compile; see the Problems panel',
    );
  });
});
