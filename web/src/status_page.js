import { element, replaceChildren } from './dom.js';
import { formatCounter } from './number_format.js';
import { counterTables, executiveSummary, linkText, task_columns, taskRows } from './status_tables.js';

// The Status page: the link, the executive's timing and every counter object of the path.
// It asks for a fresh status when shown; one comes every second anyway.
export function createStatusPage({ hub, connection }) {
  const link = document.getElementById('status-link');
  const socket = document.getElementById('status-socket');
  const executiveSection = document.getElementById('status-executive-section');
  const executiveTable = document.getElementById('status-executive');
  const tasksTable = document.getElementById('status-tasks');
  const counters = document.getElementById('status-counters');
  const updated = document.getElementById('status-updated');
  let lastStatus = null;

  const showSocket = (state) => {
    const words = { connecting: 'connecting', connected: 'connected', waiting: 'disconnected, retrying' };
    socket.textContent = `WebSocket ${state.url}: ${words[state.name] ?? state.name}`;
  };

  hub.on('link', showSocket);
  hub.on('status', (status) => {
    lastStatus = status;
    link.textContent = linkText(status.link) || (connection.connected ? 'connected (the back end reports no link state)' : 'disconnected');
    link.className = `link-state ${status.link?.state ?? ''}`;

    const summary = executiveSummary(status.executive);
    executiveSection.hidden = summary.length === 0 && taskRows(status.executive).length === 0;
    replaceChildren(executiveTable, element('tbody', {}, summary.map(([name, value]) => element('tr', {}, element('th', {}, name), element('td', {}, formatCounter(value))))));
    replaceChildren(
      tasksTable,
      element('thead', {}, element('tr', {}, task_columns.map((column) => element('th', {}, column.replace('_us', ' [us]'))))),
      element('tbody', {}, taskRows(status.executive).map((cells) => element('tr', {}, cells.map((cell, i) => element(i === 0 ? 'th' : 'td', {}, formatCounter(cell)))))),
    );

    replaceChildren(
      counters,
      counterTables(status).map(([title, rows]) =>
        element(
          'section',
          { class: 'counter-table' },
          element('h2', {}, title.replaceAll('_', ' ')),
          element('table', { 'data-status': title }, element('tbody', {}, rows.map(([name, value]) => element('tr', {}, element('th', {}, name.replaceAll('_', ' ')), element('td', {}, formatCounter(value)))))),
        ),
      ),
    );
    updated.textContent = `updated ${new Date().toLocaleTimeString()}`;
  });

  return {
    show() {
      showSocket(connection.state);
      connection.send({ type: 'status' });
    },
    hide() {},
    get lastStatus() {
      return lastStatus;
    },
  };
}
