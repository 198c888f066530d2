// The firmware vendors in pulab's order, with their names and the names of their integers: one
// list, pulab.profiles.registry, written to generated/schema.json by the build.
import schema from './generated/schema.json';
import { getLang, has, t, type Key } from './i18n';

export const VENDORS: readonly string[] = schema.vendors.map((v) => v.name);
export type Vendor = string;
const BY_NAME = new Map(schema.vendors.map((v) => [v.name, v]));

function vendor(v: Vendor): (typeof schema.vendors)[number] {
  const e = BY_NAME.get(v);
  if (!e) throw new Error(`web/src/vendors.ts: ${v} is not a vendor of pulab`);
  return e;
}

/** A vendor's name in the page's language (Inovance is 汇川). */
export function vendorName(v: Vendor): string {
  return vendor(v).label[getLang() === 'zh' ? 1 : 0];
}

/** The vendor's names of its current-loop integers (pulab's gain_fields). */
export function gainFields(v: Vendor, axis: 'd' | 'q'): [string, string] {
  const [kp, ki] = vendor(v).gain_fields[axis];
  return [kp, ki];
}

/** The file name the vendor's header is saved under. */
export function headerFile(v: Vendor): string {
  return vendor(v).header_file;
}

/** The words for choice `o` of input field `path`: a firmware by its vendor's name, else the
 * i18n text `o.PATH.O` or `o.O`. */
export function choiceText(path: string, o: string): string {
  if (path === 'conventions.firmware') return vendorName(o);
  return t((has(`o.${path}.${o}`) ? `o.${path}.${o}` : `o.${o}`) as Key);
}
