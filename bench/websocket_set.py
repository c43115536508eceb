#!/usr/bin/env python3
"""Sets an application parameter through duet-bridge's WebSocket (docs/APP_CHANNEL.md), as the dashboard does:
websocket_set.py HOST:PORT NAME=VALUE [NAME=VALUE ...]. Prints the bridge's parameter answers; exits 1 without them.
A bare RFC 6455 client (Debian's python3 has none), enough for text frames under 126 bytes."""
import base64, json, os, socket, sys


def frames(connection):
    buffer = b""
    while True:
        while len(buffer) < 2:
            buffer += connection.recv(65536)
        length, start = buffer[1] & 0x7F, 2
        if length == 126:
            length, start = int.from_bytes(buffer[2:4], "big"), 4
        elif length == 127:
            length, start = int.from_bytes(buffer[2:10], "big"), 10
        while len(buffer) < start + length:
            buffer += connection.recv(65536)
        yield buffer[start:start + length]
        buffer = buffer[start + length:]


def send_text(connection, text):
    payload, mask = text.encode(), os.urandom(4)
    assert len(payload) < 126
    masked = bytes(byte ^ mask[k % 4] for k, byte in enumerate(payload))
    connection.sendall(bytes([0x81, 0x80 | len(payload)]) + mask + masked)


host, port = sys.argv[1].rsplit(":", 1)
connection = socket.create_connection((host, int(port)), timeout=10)
key = base64.b64encode(os.urandom(16)).decode()
connection.sendall((f"GET / HTTP/1.1\r\nHost: {host}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                    f"Sec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n").encode())
response = b""
while b"\r\n\r\n" not in response:
    response += connection.recv(1)
if b" 101 " not in response.split(b"\r\n")[0]:
    sys.exit(f"websocket_set: no WebSocket at {sys.argv[1]}: {response.splitlines()[0]!r}")
wanted = {}
for assignment in sys.argv[2:]:
    name, value = assignment.split("=", 1)
    wanted[name] = float(value)
    send_text(connection, json.dumps({"type": "set", "name": name, "value": float(value)}))
for frame in frames(connection):
    message = json.loads(frame)
    if message.get("type") == "parameter" and message.get("status") != "reported" and message["name"] in wanted:
        print(f"{message['name']} = {message['value']} ({message['status']})")
        del wanted[message["name"]]
        if not wanted:
            break
    elif message.get("type") == "error":
        sys.exit(f"websocket_set: {message['message']}")
