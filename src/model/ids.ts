// Branded ids: an ElementId is never confused with a NetworkId or a plain string.
declare const brand: unique symbol;
export type Brand<T, B extends string> = T & { readonly [brand]: B };

export type ProjectId = Brand<string, 'ProjectId'>;
export type PouId = Brand<string, 'PouId'>;
export type NetworkId = Brand<string, 'NetworkId'>;
export type ElementId = Brand<string, 'ElementId'>;

let counter = 0;
/** A short id unique within this process and very likely across sessions (time + counter + random). */
export function newId<T extends string>(prefix: string): Brand<string, T> {
  counter = (counter + 1) % 1_000_000;
  const rand = Math.floor(Math.random() * 36 ** 4).toString(36);
  return `${prefix}${Date.now().toString(36)}${counter.toString(36)}${rand}` as Brand<string, T>;
}
