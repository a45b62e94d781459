// SFC POUs run as MATIEC runs them (src/engine/sfc): hand-written charts, traces computed by hand
// from MATIEC's cycle (generate_c_sfc.cc): transitions tested on the steps active at the start of
// the call, step flags and times updated, then actions by qualifier.
import { describe, expect, test } from 'vitest';
import { multiProject } from './userBlocksHelpers';
import { plcOf, trace, vars } from './ladder';
import { sfcPou, step, tr } from './sfcHelpers';

describe('SFC charts', () => {
  test('a sequence: transitions, N on a BOOL variable, step time T', () => {
    const main = sfcPou('Main', 'PROGRAM', vars('Go BOOL', 'Busy BOOL'), {
      steps: [step('Idle*'), step('Run', 'N Busy'), step('Done')],
      transitions: [tr('Idle', 'Run', 'Go'), tr('Run', 'Done', 'Run.T >= T#30ms'), tr('Done', 'Idle', 'NOT Go')],
      actions: [],
    });
    const plc = plcOf(multiProject([main]));
    expect(
      trace(plc, [{ Go: true }, {}, {}, {}, { Go: false }], ['Idle.X', 'Run.X', 'Done.X', 'Busy', 'Run.T']),
    ).toEqual([
      [0, 1, 0, 1, 0],
      [0, 1, 0, 1, 10],
      [0, 1, 0, 1, 20],
      [0, 0, 1, 0, 30],
      [1, 0, 0, 0, 30],
    ]);
  });
});
