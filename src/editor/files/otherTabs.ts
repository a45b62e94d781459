// Rungsmith open in more than one tab of one browser: the tabs share one autosave (IndexedDB and
// the localStorage journal), so each change in either overwrites the other's, and a reload brings
// back only the work of the tab changed last; the other's is lost without a word. Tabs find each
// other over a BroadcastChannel (same origin only, nothing leaves the browser): a tab says hello
// when it starts, the others answer, and each says goodbye when its page goes away.
import { createStore } from 'zustand/vanilla';

export const TABS_CHANNEL = 'rungsmith.tabs';

type TabMessage = { readonly type: 'hello' | 'here' | 'bye'; readonly tab: string };

export interface OtherTabsState {
  /** The other tabs of this browser with Rungsmith open (their ids). */
  readonly others: readonly string[];
}

export const otherTabs = createStore<OtherTabsState>()(() => ({ others: [] }));

/** What the page says while another tab has Rungsmith open. */
export const OTHER_TAB_WARNING =
  "Rungsmith is also open in another tab of this browser. The tabs share one autosave: a reload brings back only the work of the tab changed last, and the other tab's changes are lost. Work in one tab, or save to a file (File > Save) before switching.";

/**
 * Starts looking for other tabs (no-op where BroadcastChannel is missing). Returns the stop
 * function, which also tells the others this tab is gone.
 */
export function watchOtherTabs(): () => void {
  if (typeof BroadcastChannel === 'undefined') return () => undefined;
  const tab = `${Date.now().toString(36)}-${Math.random().toString(36).slice(2, 10)}`;
  const channel = new BroadcastChannel(TABS_CHANNEL);
  const set = (others: readonly string[]) => otherTabs.setState({ others });
  channel.onmessage = (e: MessageEvent<TabMessage>) => {
    const m = e.data;
    if (!m || typeof m.tab !== 'string' || m.tab === tab) return;
    const others = otherTabs.getState().others;
    if (m.type === 'bye') {
      if (others.includes(m.tab)) set(others.filter((t) => t !== m.tab));
      return;
    }
    if (!others.includes(m.tab)) set([...others, m.tab]);
    if (m.type === 'hello') channel.postMessage({ type: 'here', tab } satisfies TabMessage);
  };
  const post = (type: TabMessage['type']) => {
    try {
      channel.postMessage({ type, tab } satisfies TabMessage);
    } catch {
      // The channel is closed (the page is going away): nothing to tell.
    }
  };
  // A page kept in the back/forward cache comes back: the others forgot it when it went.
  const onShow = (e: PageTransitionEvent) => e.persisted && post('hello');
  const onHide = () => post('bye');
  window.addEventListener('pagehide', onHide);
  window.addEventListener('pageshow', onShow);
  post('hello');
  return () => {
    post('bye');
    window.removeEventListener('pagehide', onHide);
    window.removeEventListener('pageshow', onShow);
    channel.close();
    set([]);
  };
}
