// The common part of the standard function blocks: an instance whose public fields are the IEC
// pins (and internal variables), read and written by name, saved and restored as plain values.
import { blockSignature } from '../../model/blocks';
import type { ElementaryType, Value } from '../../model/iecTypes';
import { normalize } from '../values/types';

export interface FbInstance {
  readonly fbType: string;
  /** Runs the body once; `nowMs` is the time at the start of the scan (MATIEC's CURRENT_TIME). */
  execute(nowMs: number): void;
  /** Restores every pin and internal state to its initial value (cold restart). */
  reset(): void;
  get(pin: string): Value;
  /** Writes a pin, brought into the pin's type (e.g. PV wraps as an INT). */
  set(pin: string, v: Value): void;
  /** Pin names: inputs, then outputs, in signature order. */
  pins(): readonly string[];
  /** Every pin and internal field (edge memories, timer state); times relative to `timeBase`. */
  saveState(timeBase: number): FbState;
  /** Restores what saveState gave (times relative to this PLC's `timeBase`); unknown fields are ignored. */
  loadState(state: FbState, timeBase: number): void;
}

/** An FB instance's pins and internal fields as plain values (a 64-bit field F as F$hi and F$lo). */
export type FbState = Readonly<Record<string, number | boolean>>;

const HI = '$hi';
const LO = '$lo';

const pinTypes = new Map<string, ReadonlyMap<string, ElementaryType>>();

function pinTypesOf(fbType: string): ReadonlyMap<string, ElementaryType> {
  let map = pinTypes.get(fbType);
  if (!map) {
    const sig = blockSignature(fbType);
    if (!sig) throw new Error(`no signature for function block ${fbType}`);
    map = new Map([...sig.inputs, ...sig.outputs].map((p) => [p.name, p.type as ElementaryType]));
    pinTypes.set(fbType, map);
  }
  return map;
}

export abstract class StandardFb implements FbInstance {
  abstract readonly fbType: string;
  abstract execute(nowMs: number): void;
  abstract reset(): void;

  private pinType(pin: string): ElementaryType {
    const t = pinTypesOf(this.fbType).get(pin.toUpperCase());
    if (!t) throw new Error(`${this.fbType} has no pin "${pin}" (pins: ${this.pins().join(', ')})`);
    return t;
  }

  get(pin: string): Value {
    this.pinType(pin);
    return (this as unknown as Record<string, Value>)[pin.toUpperCase()]!;
  }

  set(pin: string, v: Value): void {
    const t = this.pinType(pin);
    (this as unknown as Record<string, Value>)[pin.toUpperCase()] = normalize(t, v);
  }

  pins(): readonly string[] {
    return [...pinTypesOf(this.fbType).keys()];
  }

  saveState(_timeBase: number): FbState {
    const out: Record<string, number | boolean> = {};
    for (const [k, v] of Object.entries(this))
      if (typeof v === 'number' || typeof v === 'boolean') out[k] = v;
      else if (typeof v === 'bigint') {
        // JSON and structured-clone safe, exact: the high (signed) and low 32 bits.
        out[k + HI] = Number(v >> 32n);
        out[k + LO] = Number(v & 0xffffffffn);
      }
    return out;
  }

  loadState(state: FbState, _timeBase: number): void {
    const self = this as unknown as Record<string, unknown>;
    for (const [k, v] of Object.entries(state))
      if (Object.prototype.hasOwnProperty.call(self, k) && typeof self[k] === typeof v) self[k] = v;
    for (const [k, v] of Object.entries(self)) {
      const hi = state[k + HI];
      const lo = state[k + LO];
      if (typeof v === 'bigint' && typeof hi === 'number' && typeof lo === 'number')
        this.set(k, (BigInt(hi) << 32n) + BigInt(lo));
    }
  }
}

