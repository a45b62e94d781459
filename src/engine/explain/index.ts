// "Why?" (issue 14): explanations of an element's or variable's value at one recorded scan.
export { explain } from './explain';
export type { ExplainLink, ExplainMark, ExplainTarget, Explanation, MarkRole, PathReport } from './explain';
export type { ScanView } from './view';
export { networkGraph, pathsTo } from './graph';
export { netOn } from './view';
export { liveScanView } from './liveView';
export { flattenedPou, flatNetwork } from './flatPou';
