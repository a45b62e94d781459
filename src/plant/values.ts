// A machine's readable names (issue 26): `tank.level` (a quantity) and `tank.Pump` (a point as the
// machine sees it: a sensor as sensed, an actuator as driven, an operator control as held), for the
// watch table, the trend and "Why?". Pure, for any PlantModel: the page reads them off a snapshot
// (live or recorded), the worker off its loop.
import type { Value } from '../model/iecTypes';
import type { PlantSnapshot } from './loop';
import type { PlantModel, PlantPoint, PlantQuantity, PointKind } from './types';
import { senseRecord } from './points';

export interface PlantName {
  /** `tank.level`, `tank.Pump`. */
  readonly name: string;
  readonly type: 'BOOL' | 'INT' | 'REAL';
  readonly unit?: string;
  readonly comment: string;
  readonly kind: 'quantity' | PointKind;
}

/**
 * Every readable name of the machine: its quantities, then its points. A point may be spelt like a
 * quantity but for case (the tank's `Pump` contactor beside its `pump` speed): the exact spelling
 * tells them apart (resolvePlantName).
 */
export function plantNames(model: PlantModel): PlantName[] {
  return [
    ...model.quantities.map((q) => ({
      name: `${model.id}.${q.name}`,
      type: q.type,
      ...(q.unit ? { unit: q.unit } : {}),
      comment: q.comment,
      kind: 'quantity' as const,
    })),
    ...model.points.map((p) => ({ name: `${model.id}.${p.name}`, type: p.type, comment: p.comment, kind: p.kind })),
  ];
}

export type PlantNameRef =
  | { readonly quantity: PlantQuantity; readonly point?: undefined }
  | { readonly point: PlantPoint; readonly quantity?: undefined };

/**
 * What a bare name (`level`, `Pump`) names: spelt exactly, a quantity or a point (`pump` is the
 * tank's pump speed, `Pump` its contactor); else, in any case, a quantity first, then a point.
 */
export function resolvePlantName(model: PlantModel, bare: string): PlantNameRef | undefined {
  const quantity = model.quantities.find((q) => q.name === bare);
  if (quantity) return { quantity };
  const point = model.points.find((p) => p.name === bare);
  if (point) return { point };
  const lower = bare.toLowerCase();
  const q = model.quantities.find((x) => x.name.toLowerCase() === lower);
  if (q) return { quantity: q };
  const p = model.points.find((x) => x.name.toLowerCase() === lower);
  return p ? { point: p } : undefined;
}

/** What `tank.level` (the machine's id first, in any case) names, or undefined. */
export function findPlantName(model: PlantModel, name: string): PlantNameRef | undefined {
  const prefix = `${model.id}.`;
  if (!name.toLowerCase().startsWith(prefix)) return undefined;
  return resolvePlantName(model, name.slice(prefix.length));
}

/** The machine's own spelling of a name it has (`TANK.LEVEL` -> `tank.level`), or undefined. */
export function plantSpelling(model: PlantModel, name: string): string | undefined {
  const ref = findPlantName(model, name);
  return ref && `${model.id}.${ref.quantity?.name ?? ref.point!.name}`;
}

/**
 * The value of `tank.level` or `tank.Pump` in a snapshot (a live frame's or a recorded scan's);
 * undefined for a name the machine does not have, or an actuator when the snapshot has no drive.
 */
export function plantValue(model: PlantModel, snapshot: PlantSnapshot, name: string): Value | undefined {
  const ref = findPlantName(model, name);
  if (!ref) return undefined;
  if (ref.quantity) return model.quantity(snapshot.state, ref.quantity.name);
  const p = ref.point;
  if (p.kind === 'operator') return snapshot.operator[p.name] === true;
  if (p.kind === 'sensor') return senseRecord(model, snapshot.state, new Set(snapshot.faults))[p.name];
  return snapshot.drive?.[p.name];
}

/** `812.4 L`, `TRUE`, `3`: a machine value as the watch table and "Why?" show it. */
export function formatPlantValue(type: PlantName['type'], value: Value, unit?: string): string {
  const text =
    typeof value === 'boolean'
      ? value
        ? 'TRUE'
        : 'FALSE'
      : type === 'REAL'
        ? Number(value).toFixed(1)
        : String(value);
  return unit ? `${text} ${unit}` : text;
}

/** The machine's quantities in a snapshot, in words: `level 812.4 L, pump 100.0 %, overflowing FALSE`. */
export function describeQuantities(model: PlantModel, snapshot: PlantSnapshot): string {
  return model.quantities
    .map((q) => `${q.name} ${formatPlantValue(q.type, model.quantity(snapshot.state, q.name), q.unit)}`)
    .join(', ');
}
