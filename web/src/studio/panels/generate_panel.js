import { element, replaceChildren } from '../../dom.js';
import { formatSize, taskRows } from './generated_tables.js';

// Generated: what code generation makes of the editor's text (the files, to read), the task
// table and the schedulability verdict.
export function createGeneratePanel({ element: root, hub, connection, getText }) {
  let files = [];
  let shownFile = null; // its name, kept across generations while it still exists
  let waiting = false;
  // The times the verdict needs and no model holds, by task function (step_rate_1, task_EXTI8), kept across
  // generations: worst-case execution times, and interrupt tasks' shortest times between triggers.
  const times = { wcet_us: new Map(), interarrival_us: new Map() };

  root.classList.add('studio-panel', 'generate-panel');
  const generateButton = element('button', { type: 'button', class: 'primary', onclick: generate }, 'Generate');
  const verdict = element('strong', { class: 'verdict', hidden: true });
  const message = element('span', { class: 'panel-message', role: 'status' });
  const fileList = element('ul', { class: 'file-list', 'aria-label': 'generated files' });
  const fileText = element('pre', { class: 'file-text' });
  const taskTable = element('div', { class: 'task-table' });
  const report = element('pre', { class: 'report' });
  root.replaceChildren(
    element('div', { class: 'panel-toolbar' }, generateButton, verdict, message),
    element(
      'div',
      { class: 'generated' },
      element('section', { class: 'files' }, element('h3', {}, 'Files'), fileList),
      element('section', { class: 'file' }, fileText),
      element('section', { class: 'schedule' }, element('h3', {}, 'Tasks'), taskTable, element('h3', {}, 'Schedulability'), report),
    ),
  );
  fileText.textContent = 'Generate to see the code made of the text in the editor.';

  function say(text, tone = 'muted') {
    message.textContent = text;
    message.className = `panel-message ${tone}`;
  }

  function given(map) {
    return Object.fromEntries([...map].filter(([, value]) => Number.isFinite(value) && value > 0));
  }

  function generate() {
    const request = { type: 'generate', text: getText(), wcet_us: given(times.wcet_us), interarrival_us: given(times.interarrival_us) };
    if (!connection.send(request)) return say('not connected to duet studio', 'bad');
    waiting = true;
    generateButton.disabled = true;
    say('generating…');
  }

  function finished() {
    waiting = false;
    generateButton.disabled = false;
  }

  hub.on('generated', (generated) => {
    finished();
    say('');
    files = generated.files ?? [];
    if (!files.some((file) => file.name === shownFile)) shownFile = files[0]?.name ?? null;
    showFiles();
    showTasks(generated.tasks);
    showVerdict(generated.schedulability);
  });

  hub.on('error', (error) => {
    if (error.request !== 'generate') return;
    if (waiting) finished();
    // What shows below stays the last generation that worked; say so rather than clear it.
    say(`generation failed: ${error.message}${files.length > 0 ? ' (below: the last generation that worked)' : ''}`, 'bad');
  });

  // The page's socket dropped: the answer cannot come any more.
  hub.on('link', (link) => {
    if (link.name === 'connected' || !waiting) return;
    finished();
    say('the connection to duet studio was lost; generate again', 'bad');
  });

  function showFiles() {
    replaceChildren(
      fileList,
      files.map((file) =>
        element(
          'li',
          {},
          element(
            'button',
            {
              type: 'button',
              'aria-current': file.name === shownFile ? 'true' : undefined,
              onclick: () => {
                shownFile = file.name;
                showFiles();
              },
            },
            element('span', { class: 'file-name' }, file.name),
            element('span', { class: 'file-size muted' }, formatSize(file.text)),
          ),
        ),
      ),
    );
    const file = files.find((candidate) => candidate.name === shownFile);
    fileText.textContent = file ? file.text : 'No files were generated.';
    fileText.scrollTop = 0;
  }

  // A time the user gives for the verdict; the next Generate sends it.
  function timeField(kind, task) {
    const input = element('input', {
      type: 'number', min: '0', step: 'any', inputmode: 'decimal', 'data-time': kind, 'data-task': task.function,
      value: times[kind].has(task.function) ? String(times[kind].get(task.function)) : '',
      title: kind === 'wcet_us' ? 'worst-case execution time, µs' : 'shortest time between two triggers, µs',
    });
    input.addEventListener('input', () => {
      const value = Number(input.value);
      if (input.value === '' || !(value > 0)) times[kind].delete(task.function);
      else times[kind].set(task.function, value);
    });
    return input;
  }

  function showTasks(tasks) {
    const rows = taskRows(tasks);
    if (rows.length === 0) return replaceChildren(taskTable, element('p', { class: 'muted' }, 'no tasks'));
    const headings = ['task', 'kind', 'period or interrupt', 'blocks', 'WCET [µs]', 'min. interarrival [µs]'];
    replaceChildren(
      taskTable,
      element(
        'table',
        {},
        element('thead', {}, element('tr', {}, headings.map((heading) => element('th', {}, heading)))),
        element('tbody', {}, rows.map((cells, index) => element('tr', {},
          cells.map((cell) => element('td', {}, cell)),
          element('td', {}, timeField('wcet_us', tasks[index])),
          element('td', {}, tasks[index].kind === 'interrupt' ? timeField('interarrival_us', tasks[index]) : null)))),
      ),
      element('p', { class: 'muted' }, 'The verdict needs every task\'s execution time and every interrupt task\'s shortest time between triggers: give them here and Generate again. Connected to a target (Live), its measured longest execution times stand in.'),
    );
  }

  function showVerdict(schedulability) {
    verdict.hidden = !schedulability;
    if (!schedulability) {
      report.textContent = '';
      return;
    }
    verdict.textContent = schedulability.verdict ?? (schedulability.schedulable ? 'schedulable' : 'not schedulable');
    const tone = schedulability.schedulable === null || schedulability.schedulable === undefined ? 'warn' : schedulability.schedulable ? 'good' : 'bad';
    verdict.className = `verdict ${tone}`;
    report.textContent = schedulability.report ?? '';
  }

  return {};
}
