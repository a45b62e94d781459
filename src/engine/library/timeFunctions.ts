// Functions of TIME (IEC 61131-3 table 30, the ones without dates): ADD_TIME, SUB_TIME, MULTIME,
// DIVTIME, as MATIEC's iec_std_functions.h. MULTIME/DIVTIME multiply or divide by the number
// converted to LREAL (MATIEC __time_mul/__time_div); the result is rounded to whole milliseconds,
// the resolution of TIME here (MATIEC keeps nanoseconds). DIVTIME by 0 is undefined behaviour in
// MATIEC's C (a double infinity cast to an integer): here it is an error, ENO OFF, output kept.
import { normalize } from '../values/types';
import { num, type FnImpl2 } from './fnTypes';

export type TimeFunctionName = 'ADD_TIME' | 'SUB_TIME' | 'MULTIME' | 'DIVTIME';

export const isTimeFunction = (name: string): name is TimeFunctionName =>
  name === 'ADD_TIME' || name === 'SUB_TIME' || name === 'MULTIME' || name === 'DIVTIME';

export function timeFunction(name: TimeFunctionName): FnImpl2 {
  switch (name) {
    case 'ADD_TIME':
      return (_c, a, b) => (a as number) + (b as number);
    case 'SUB_TIME':
      return (_c, a, b) => (a as number) - (b as number);
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
  }
}
