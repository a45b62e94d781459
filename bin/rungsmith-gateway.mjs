#!/usr/bin/env node
// The gateway: serves the app and the WebSocket endpoint /io on 127.0.0.1 (see docs/gateway.md).
// The gateway is TypeScript; tsx's loader runs it without a separate compile step.
import { register } from 'tsx/esm/api';

register();
await import(new URL('../src/gateway/main.ts', import.meta.url).href);
