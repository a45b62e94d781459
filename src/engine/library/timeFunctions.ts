// Functions of TIME (IEC 61131-3 table 30, the ones without dates): ADD_TIME, SUB_TIME, MULTIME,
// DIVTIME, as MATIEC's iec_std_functions.h. MULTIME/DIVTIME multiply or divide by the number
// converted to LREAL (MATIEC __time_mul/__time_div); the result is rounded to whole milliseconds,
// the resolution of TIME here (MATIEC keeps nanoseconds). DIVTIME by 0 is undefined behaviour in
// MATIEC's C (a double infinity cast to an integer): here it is an error, ENO OFF, output kept.
import { normalize } from '../values/types';
import { num, type FnImpl2 } from './fnTypes';

// The date functions (ADD_TOD_TIME ... CONCAT_DATE_TOD) add and subtract milliseconds as MATIEC's
// __time_add/__time_sub add timespecs: a TOD is not wrapped at midnight.
const ADDS = ['ADD_TIME', 'ADD_TOD_TIME', 'ADD_DT_TIME', 'CONCAT_DATE_TOD'] as const;
const SUBS = ['SUB_TIME', 'SUB_DATE_DATE', 'SUB_TOD_TIME', 'SUB_TOD_TOD', 'SUB_DT_TIME', 'SUB_DT_DT'] as const;

export type TimeFunctionName = (typeof ADDS)[number] | (typeof SUBS)[number] | 'MULTIME' | 'DIVTIME';

export const isTimeFunction = (name: string): name is TimeFunctionName =>
  (ADDS as readonly string[]).includes(name) || (SUBS as readonly string[]).includes(name) || name === 'MULTIME' || name === 'DIVTIME';

export function timeFunction(name: TimeFunctionName): FnImpl2 {
  if ((ADDS as readonly string[]).includes(name)) return (_c, a, b) => (a as number) + (b as number);
  if ((SUBS as readonly string[]).includes(name)) return (_c, a, b) => (a as number) - (b as number);
  switch (name) {
    case 'MULTIME':
      return (_c, a, b) => normalize('TIME', (a as number) * num(b));
    case 'DIVTIME':
      return (ctx, a, b) => {
        const d = num(b);
        if (d === 0) {
          ctx.error = true;
          return 0;
        }
        return normalize('TIME', (a as number) / d);
      };
    default:
      throw new Error(`${name} is not a TIME function`);
  }
}
