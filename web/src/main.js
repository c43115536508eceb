// duet's dashboard: one WebSocket, four pages. This file only wires the parts together.
import { Connection } from './connection.js';
import { EventHub } from './event_hub.js';
import { websocketUrl } from './websocket_url.js';
import { installTestHooks, recordMessage } from './test_hooks.js';
import { connectSignalFeed } from './signal_feed.js';
import { createLinkIndicator } from './link_indicator.js';
import { createTuningPage } from './tuning_page.js';
import { createPlantControls } from './plant_controls.js';
import { createScopePage } from './scope_page.js';
import { createRecorderPage } from './recorder_page.js';
import { createStatusPage } from './status_page.js';
import { createMdf4Files } from './mdf4_files.js';
import { downloadBlob } from './download.js';
import { createValuesPanel } from './values_panel.js';
import { setUpTabs } from './tabs.js';

const hub = new EventHub();
const indicator = createLinkIndicator(document.getElementById('link-indicator'));
const backendUrl = websocketUrl(location);
// Before the pages: they show or hide their MDF4 buttons on the same description.
const mdf4 = createMdf4Files({ websocketUrl: backendUrl, fetchFile: (url, init) => fetch(url, init), save: downloadBlob });
hub.on('description', (description) => mdf4.describe(description));
const connection = new Connection(backendUrl, {
  onMessage(message, arrivalMs) {
    recordMessage(duet, message, arrivalMs);
    hub.emit(message.type, message);
  },
  onState(state) {
    indicator.socket(state);
    hub.emit('link', state);
  },
});
const duet = installTestHooks(connection);

connectSignalFeed(hub, duet.stats);
createValuesPanel({ hub, node: document.getElementById('tuning-now') });
hub.on('channel', (channel) => indicator.channel(channel.open !== false));
hub.on('description', () => indicator.channel(true));

const pages = {
  tuning: createTuningPage({ hub, connection }),
  scope: createScopePage({ hub, stats: duet.stats, mdf4 }),
  recorder: createRecorderPage({ hub, connection, mdf4 }),
  status: createStatusPage({ hub, connection }),
};
createPlantControls({ hub, connection, root: document.getElementById('plant-controls') });
setUpTabs(pages, 'tuning');
connection.open();
