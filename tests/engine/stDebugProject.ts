// Test helper: an LD program calling an ST FB (which calls an LD FB), for debugging ST.
import { ladder, type BoxSpec } from './ladder';
import { io, stProject, textPou, vars } from './stHelpers';
import { pou } from './userBlocksHelpers';

export const box = (type: string, row: number, col: number, extra: Partial<BoxSpec> = {}): BoxSpec => ({ row, col, type, ...extra });

// Hyst (ST FB) calls Lamp (LD FB) on line 9; Main (LD) calls Hyst as H1 in network 2 and H2 in network 3.
export const HYST = [
  'IF X > Hi THEN', // 1
  '  Q := TRUE;', // 2
  'ELSIF X < Lo THEN', // 3
  '  Q := FALSE;', // 4
  'END_IF;', // 5
  'Count := Count + 1;', // 6
  'Count := Count * 2;', // 7
  'Twice := Count;', // 8
  'L(On := Q, Lit => Shown);', // 9
].join('\n');

export function project() {
  const lamp = pou('Lamp', 'FUNCTION_BLOCK', [...io('input', 'On BOOL'), ...io('output', 'Lit BOOL')], [ladder(['[On] (Lit)'])]);
  const hyst = textPou(
    'Hyst',
    'FUNCTION_BLOCK',
    [...io('input', 'X INT', 'Hi INT', 'Lo INT'), ...io('output', 'Q BOOL', 'Shown BOOL'), ...vars('Count INT', 'Twice INT', 'L Lamp')],
    HYST,
  );
  const main = pou('Main', 'PROGRAM', vars('Go BOOL', 'Level INT', 'Other INT', 'On1 BOOL', 'On2 BOOL', 'Before BOOL', 'After BOOL', 'H1 Hyst', 'H2 Hyst'), [
    ladder(['[Go] (Before)']),
    ladder(['[Go] # # (On1)', '. # # .', '. # # .', '. # # .'], {
      boxes: [box('Hyst', 0, 1, { instance: 'H1', executionControl: true, inputs: { X: 'Level', Hi: '10', Lo: '5' } })],
    }),
    ladder(['[Go] # # (On2)', '. # # .', '. # # .', '. # # .'], {
      boxes: [box('Hyst', 0, 1, { instance: 'H2', executionControl: true, inputs: { X: 'Other', Hi: '10', Lo: '5' } })],
    }),
    ladder(['[Go] (After)']),
  ]);
  return stProject([main, hyst, lamp]);
}

