// Canvas layout benchmark (Node): laying out 1,000 networks (~11,000 elements) whose columns are
// sized from their names (src/editor/canvas/columns.ts). Prints the cold layout (every network's
// columns measured), the warm one (an edit elsewhere: columns reused per unchanged network
// object), and one network's columns after an edit. Run with `npx tsx bench/canvasLayout.bench.ts`.
import { networkColumns } from '../src/editor/canvas/columns';
import { layoutNetworks } from '../src/editor/canvas/geometry';
import { blockLibrary } from '../src/model/library';
import type { Network } from '../src/model/project';
import { sealInProject } from '../tests/e2e/sealInProject';
import { median } from './median';

const NETWORKS = 1000;

const project = sealInProject(NETWORKS);
const library = blockLibrary(project);
const networks = project.pous[0]!.networks;
/** Fresh network objects each run: nothing memoised (as after loading a project). */
const fresh = (): Network[] => networks.map((n) => ({ ...n }));

const cold = median(15, () => layoutNetworks(fresh(), library));
layoutNetworks(networks, library);
const warm = median(15, () => layoutNetworks(networks, library));
const one = median(101, () => networkColumns({ ...networks[500]! }, library));
const elements = networks.reduce((s, n) => s + n.elements.length, 0);

console.log(`canvas layout, ${NETWORKS} networks (${elements} elements), median ms:`);
console.log(`  cold (columns measured for every network): ${cold.toFixed(2)}`);
console.log(`  warm (columns reused, e.g. after an edit elsewhere): ${warm.toFixed(2)}`);
console.log(`  one edited network's columns: ${(one * 1000).toFixed(1)} µs`);
