// Keeps the simulator's machine in step with the project's (`project.plant`, issue 26): opening a
// project or example that names a machine attaches it; choosing another in the Plant panel, or
// changing an address, re-attaches it. While this page drives the hardware (connected to the
// gateway as controller), the machine is set aside: the program's inputs come from the device, and
// a simulated sensor must never decide what real outputs do (a simulated high level switch while
// the real tank overflows). It is attached again, from its initial state, when the hardware is
// left. Mounted once (panels.ts HOSTS).
import { useEffect, useRef } from 'react';
import type { DocumentState } from '../../store/documentStore';
import { useDocument } from '../../store/documentStore';
import { useSimStore } from '../sim/simContext';
import { useGateway } from '../hardware/useGateway';
import { plantById } from '../../plant/machines';
import type { SimState } from '../../store/simState';
import { controlsOf, loadKeptControls, saveKeptControls } from './keptControls';

const selectPlant = (s: DocumentState) => s.project.plant;

/** The page drives the hardware: the machine in the Plant panel is set aside. */
export function useHardwareAttached(): boolean {
  const { link, role } = useGateway();
  return link === 'open' && role === 'controller';
}

export function PlantHost() {
  const plant = useDocument(selectPlant);
  const hardware = useHardwareAttached();
  const sim = useSimStore();
  const sent = useRef<string>('null');
  // The faults and switches of the page before a reload are given back once, to the first machine
  // attached (the restored project's), as Reset keeps them; from then on they are kept as they change.
  const restored = useRef(false);
  useEffect(() => {
    const keep = (s: SimState) => {
      if (restored.current) saveKeptControls(controlsOf(s.plant));
    };
    keep(sim.getState());
    return sim.subscribe((s, prev) => {
      if (s.plant !== prev.plant) keep(s);
    });
  }, [sim]);
  useEffect(() => {
    const attached = plant && !hardware ? plant : null;
    const key = JSON.stringify(attached);
    if (key === sent.current) return;
    const setAside = plant !== undefined && hardware && sent.current !== 'null';
    sent.current = key;
    sim.getState().setPlant(attached ? { id: attached.id, ...(attached.map ? { map: attached.map } : {}) } : null);
    if (attached && !restored.current) {
      restored.current = true;
      const model = plantById(attached.id);
      const kept = model && loadKeptControls(model.id);
      if (model && kept) {
        for (const f of kept.faults) if (model.faults.some((m) => m.id === f)) sim.getState().plantFault(f, true);
        for (const name of kept.switches)
          if (model.points.some((p) => p.name === name && p.kind === 'operator' && p.control === 'switch'))
            sim.getState().plantOperator(name, true);
      }
    }
    if (setAside)
      sim.setState({
        notice: `The machine ${plant.id} is set aside while the hardware is attached: the program's inputs come from the device. It is back when you disconnect.`,
      });
  }, [plant, hardware, sim]);
  return null;
}
