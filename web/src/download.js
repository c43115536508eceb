// Offers `text` as a file download, without a server round trip.
export function downloadText(filename, text, type = 'text/plain') {
  downloadBlob(filename, new Blob([text], { type }));
}

// Offers `blob` (the page's own, or what the back end answered) as a file download.
export function downloadBlob(filename, blob) {
  const url = URL.createObjectURL(blob);
  const link = document.createElement('a');
  link.href = url;
  link.download = filename;
  document.body.append(link);
  link.click();
  link.remove();
  // The browser has the blob once the click is handled; give it a moment before freeing it.
  setTimeout(() => URL.revokeObjectURL(url), 10000);
}

// 2024-05-01T12-30-05: sortable and valid in every file system.
export function timestampForFile(date = new Date()) {
  return date.toISOString().slice(0, 19).replaceAll(':', '-');
}
