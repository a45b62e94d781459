/**
 * The page's side of the gateway link held by the simulation worker (src/bridge/workerRelay.ts):
 *   workerSocketFactory(transport)  a SocketFactory for GatewayClient whose sockets live in the worker;
 *   workerDriver(transport)         starts/ends the worker's drive of the hardware (GatewayBridge).
 * A worker that dies (terminated, crashed) closes its sockets: the gateway's lease ends at once.
 */
import type { SimTransport } from '../sim/host';
import type { DriveBinding, WorkerMessage } from '../sim/protocol';
import type { SocketFactory, SocketLike } from './GatewayClient';
import type { Binding } from './mapping';

let ids = 0;

class WorkerSocket implements SocketLike {
  readyState = 0;
  onopen: ((ev: unknown) => void) | null = null;
  onmessage: ((ev: { data: unknown }) => void) | null = null;
  onclose: ((ev: { code: number; reason: string }) => void) | null = null;
  onerror: ((ev: unknown) => void) | null = null;
  private readonly id = ++ids;
  private readonly unlisten: () => void;

  constructor(
    private readonly transport: SimTransport,
    url: string,
  ) {
    this.unlisten = transport.listen((m: WorkerMessage) => {
      if (m.type === 'gwEvent' && m.id === this.id) this.event(m);
      // A worker that crashed took its sockets with it.
      else if (m.type === 'error' && m.message.startsWith('the simulator stopped') && this.readyState < 3) this.closed(1006, 'the simulation worker stopped');
    });
    transport.send({ type: 'gwOpen', id: this.id, url });
  }

  private event(m: Extract<WorkerMessage, { type: 'gwEvent' }>): void {
    if (m.event === 'open') {
      this.readyState = 1;
      this.onopen?.({});
    } else if (m.event === 'message') {
      this.onmessage?.({ data: m.data });
    } else {
      this.closed(m.code ?? 1006, m.reason ?? '');
    }
  }

  private closed(code: number, reason: string): void {
    if (this.readyState === 3) return;
    this.readyState = 3;
    this.unlisten();
    this.onclose?.({ code, reason });
  }

  send(data: string): void {
    if (this.readyState === 1) this.transport.send({ type: 'gwSend', id: this.id, data });
  }

  close(code?: number, reason?: string): void {
    if (this.readyState >= 2) return;
    this.readyState = 2;
    this.transport.send({ type: 'gwClose', id: this.id, ...(code !== undefined ? { code } : {}), ...(reason !== undefined ? { reason } : {}) });
    this.closed(code ?? 1000, reason ?? '');
  }
}

export function workerSocketFactory(transport: SimTransport): SocketFactory {
  return (url) => new WorkerSocket(transport, url);
}

/** How the page has the program drive the hardware (GatewayBridge.attach / the stepping lease). */
export interface ProgramDriver {
  /** The worker applies the gateway's inputs and sends the outputs and heartbeat; returns the function that ends it. */
  drive(bindings: readonly Binding[], kind: 'run' | 'step'): () => void;
  /** Called with why when the worker ended a drive by itself (program stopped, link closed). */
  onEnded(listener: (reason: string) => void): () => void;
}

export function workerDriver(transport: SimTransport): ProgramDriver {
  let generation = 0;
  return {
    drive(bindings, kind) {
      const mine = ++generation;
      const data: DriveBinding[] = bindings.map((b) => ({ address: b.address, varType: b.varType, dir: b.point.dir }));
      transport.send({ type: 'gwDrive', drive: { bindings: data, kind } });
      return () => {
        if (generation !== mine) return; // a newer drive replaced this one
        generation++;
        transport.send({ type: 'gwDrive', drive: null });
      };
    },
    onEnded(listener) {
      return transport.listen((m) => {
        if (m.type === 'gwDriveEnded') listener(m.reason);
      });
    },
  };
}
