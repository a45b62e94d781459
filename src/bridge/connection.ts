// Where the gateway is: its WebSocket URL from the page URL, the token from the URL fragment.
import { IO_PATH } from '../protocol/messages';

/** `http://127.0.0.1:8080/anything` -> `ws://127.0.0.1:8080/io` (https -> wss). Undefined for text that is not a URL. */
export function gatewaySocketUrl(gatewayUrl: string): string | undefined {
  let u: URL;
  try {
    u = new URL(gatewayUrl.includes('://') ? gatewayUrl : `http://${gatewayUrl}`);
  } catch {
    return undefined;
  }
  const scheme = u.protocol === 'https:' || u.protocol === 'wss:' ? 'wss:' : u.protocol === 'http:' || u.protocol === 'ws:' ? 'ws:' : undefined;
  if (!scheme) return undefined;
  return `${scheme}//${u.host}${IO_PATH}`;
}

/** The token from a fragment such as `#token=abc` (the gateway prints it that way; never a query string). */
export function tokenFromFragment(hash: string): string | undefined {
  const params = new URLSearchParams(hash.replace(/^#/, ''));
  const token = params.get('token');
  return token ? token : undefined;
}
