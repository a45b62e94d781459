// The page's one link to a gateway, shared by the Hardware panel (connect, show) and the
// simulation (GatewayBridge). Plain TypeScript: UI subscribes to it.
import type { Role } from '../protocol/messages';
import { gatewaySocketUrl } from './connection';
import { GatewayBridge } from './GatewayBridge';
import { GatewayClient, IDLE_VIEW, type GatewayView, type SocketFactory } from './GatewayClient';
import type { SimTransport } from '../sim/host';
import { workerDriver, workerSocketFactory, type ProgramDriver } from './workerSocket';

export interface LinkTarget {
  /** The gateway's page URL (http://127.0.0.1:8080/) or host:port. */
  readonly gatewayUrl: string;
  readonly token: string;
  readonly role: Role;
}

export class GatewayLink {
  private current: { client: GatewayClient; bridge: GatewayBridge; unsubscribe: () => void } | undefined;
  private readonly listeners = new Set<() => void>();
  private view: GatewayView = IDLE_VIEW;

  private driver: ProgramDriver | undefined;

  constructor(private socketFactory?: SocketFactory) {}

  /**
   * The page: the link's socket lives in the simulation worker, which drives the hardware while the
   * program runs (src/bridge/workerRelay.ts). Applies from the next connect.
   */
  useWorker(transport: SimTransport): void {
    this.socketFactory = workerSocketFactory(transport);
    this.driver = workerDriver(transport);
  }

  /** Opens the link; returns an error in plain words when the URL or token cannot be used. */
  connect(target: LinkTarget): string | null {
    const socketUrl = gatewaySocketUrl(target.gatewayUrl.trim());
    if (!socketUrl) return `"${target.gatewayUrl}" is not a gateway URL; use e.g. http://127.0.0.1:8080/`;
    if (!target.token.trim()) return 'the token is empty: open the URL the gateway printed (…/#token=…) or paste its token';
    this.disconnect();
    const client = new GatewayClient({ socketUrl, token: target.token.trim(), role: target.role, socketFactory: this.socketFactory });
    const unsubscribe = client.subscribe((v) => this.set(v));
    this.current = { client, bridge: new GatewayBridge(client, this.driver), unsubscribe };
    client.connect();
    return null;
  }

  disconnect(): void {
    const c = this.current;
    this.current = undefined;
    if (c) {
      c.bridge.stop();
      c.unsubscribe();
      c.client.disconnect();
    }
    this.set(IDLE_VIEW);
  }

  get client(): GatewayClient | undefined {
    return this.current?.client;
  }

  /** The simulation's bridge while a link exists (see GatewayBridge.ts). */
  get bridge(): GatewayBridge | undefined {
    return this.current?.bridge;
  }

  snapshot = (): GatewayView => this.view;

  subscribe = (listener: () => void): (() => void) => {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  };

  private set(v: GatewayView): void {
    this.view = v;
    this.listeners.forEach((l) => l());
  }
}

/** The page's gateway link. */
export const gatewayLink = new GatewayLink();
