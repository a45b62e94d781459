// Keeps the simulator's machine in step with the project's (`project.plant`, issue 26): opening a
// project or example that names a machine attaches it; choosing another in the Plant panel, or
// changing an address, re-attaches it. Mounted once (panels.ts HOSTS).
import { useEffect, useRef } from 'react';
import type { DocumentState } from '../../store/documentStore';
import { useDocument } from '../../store/documentStore';
import { useSimStore } from '../sim/simContext';

const selectPlant = (s: DocumentState) => s.project.plant;

export function PlantHost() {
  const plant = useDocument(selectPlant);
  const sim = useSimStore();
  const sent = useRef<string>('null');
  useEffect(() => {
    const key = JSON.stringify(plant ?? null);
    if (key === sent.current) return;
    sent.current = key;
    sim.getState().setPlant(plant ? { id: plant.id, ...(plant.map ? { map: plant.map } : {}) } : null);
  }, [plant, sim]);
  return null;
}
