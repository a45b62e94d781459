// BCD conversions of OpenPLC Editor's palette (BCD_TO_USINT ... BCD_TO_ULINT, USINT_TO_BCD ...
// ULINT_TO_BCD), as MATIEC's __bcd_to_uint / __uint_to_bcd (lib/C/iec_std_lib.h):
// - BCD_TO_*: a nibble above 9 is not BCD: ENO OFF (MATIEC TEST_EN_COND(__test_bcd)), and the
//   output variable keeps its value; else the decimal value, wrapped to the target type.
// - *_TO_BCD: one decimal digit per nibble, ENO ON; digits beyond the target's width are lost
//   (USINT_TO_BCD(255) = 16#55, the hundreds digit does not fit a BYTE).
import type { ElementaryType } from '../../model/iecTypes';
import { normalize } from '../values/types';
import type { FnImpl1 } from './fnTypes';

const bigOf = (v: unknown): bigint => (typeof v === 'bigint' ? v : BigInt(v as number));

export function bcdToInt(to: ElementaryType): FnImpl1 {
  return (ctx, a) => {
    let v = bigOf(a);
    let result = 0n;
    let factor = 1n;
    while (v) {
      const digit = v & 0xfn;
      if (digit > 9n) {
        ctx.error = true;
        return normalize(to, 0);
      }
      result += digit * factor;
      factor *= 10n;
      v >>= 4n;
    }
    return normalize(to, result);
  };
}

export function intToBcd(to: ElementaryType): FnImpl1 {
  return (_c, a) => {
    let v = bigOf(a);
    let result = 0n;
    let shift = 0n;
    do {
      result |= (v % 10n) << shift;
      shift += 4n;
      v /= 10n;
    } while (v);
    return normalize(to, result);
  };
}
