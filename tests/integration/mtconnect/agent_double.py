# An MTConnect agent double for the capture tests: serves /current and /sample?from=&count=
# (MTConnect Part 1/3 answers, written here from the standard's document structure) for one
# device whose observations come from a recording, released one every --period-ms as a
# controller would produce them. Faults on request:
#   --buffer K        the agent keeps only its last K observations (older `from`: OUT_OF_RANGE)
#   --shuffle         observations of an answer are written out of sequence order
#   --drop-every N    every N-th request is answered by closing the connection
# Recording: one observation a line, "Name value" or "Name@subType value".
# Writes the port it listens on to --port-file.
import argparse
import http.server
import random
import threading
import time
import urllib.parse
from xml.sax.saxutils import escape

p = argparse.ArgumentParser()
p.add_argument("--recording", required=True)
p.add_argument("--device", default="mill2")
p.add_argument("--period-ms", type=float, default=20)
p.add_argument("--buffer", type=int, default=131072)
p.add_argument("--shuffle", action="store_true")
p.add_argument("--drop-every", type=int, default=0)
p.add_argument("--port-file", required=True)
args = p.parse_args()

INSTANCE = 1732600000
recorded = []
with open(args.recording) as f:
    for line in f:
        line = line.rstrip("\n")
        if not line.strip():
            continue
        head, _, value = line.partition(" ")
        name, _, sub = head.partition("@")
        recorded.append((name, sub, value))
# Sequence 1.. in recording order; the agent starts with every item UNAVAILABLE (as real
# agents do), then the recording follows.
items = sorted({(n, s) for n, s, _ in recorded})
observations = [(i + 1, n, s, "UNAVAILABLE") for i, (n, s) in enumerate(items)]
base = len(observations)
for i, (n, s, v) in enumerate(recorded):
    observations.append((base + i + 1, n, s, v))
start = None  # the recording starts at the first request (a controller starting its run then)
requests = 0
lock = threading.Lock()


def available():
    if start is None:
        return base
    released = base + int((time.time() - start) * 1000 / args.period_ms)
    return min(released, len(observations))


def header(first, nxt):
    return ('<Header creationTime="2026-11-26T08:00:00Z" sender="double" instanceId="%d" version="1.7.0" '
            'bufferSize="%d" firstSequence="%d" lastSequence="%d" nextSequence="%d"/>'
            % (INSTANCE, args.buffer, first, nxt - 1, nxt))


def streams(first, nxt, chosen):
    if args.shuffle:
        chosen = chosen[:]
        random.shuffle(chosen)
    events = []
    for seq, name, sub, value in chosen:
        attr = ' subType="%s"' % sub if sub else ""
        events.append('<%s dataItemId="%s" timestamp="2026-11-26T08:00:00Z" sequence="%d"%s>%s</%s>'
                      % (name, name.lower(), seq, attr, escape(value), name))
    return ('<?xml version="1.0" encoding="UTF-8"?>\n'
            '<MTConnectStreams xmlns="urn:mtconnect.org:MTConnectStreams:1.7">' + header(first, nxt) +
            '<Streams><DeviceStream name="%s" uuid="%s-uuid"><ComponentStream component="Path" name="path" '
            'componentId="p1"><Events>%s</Events></ComponentStream></DeviceStream></Streams></MTConnectStreams>'
            % (args.device, args.device, "".join(events)))


def error(code, text):
    return ('<?xml version="1.0" encoding="UTF-8"?>\n<MTConnectError xmlns="urn:mtconnect.org:MTConnectError:1.7">'
            + header(1, 1) + '<Errors><Error errorCode="%s">%s</Error></Errors></MTConnectError>' % (code, escape(text)))


class Agent(http.server.BaseHTTPRequestHandler):
    def log_message(self, *a):
        pass

    def answer(self, status, body):
        data = body.encode()
        self.send_response(status)
        self.send_header("Content-Type", "application/xml")
        self.send_header("Content-Length", str(len(data)))
        self.end_headers()
        self.wfile.write(data)

    def do_GET(self):
        global requests, start
        with lock:
            requests += 1
            n = requests
            if start is None:
                start = time.time()
        if args.drop_every and n % args.drop_every == 0:
            self.close_connection = True
            self.connection.shutdown(2)
            return
        url = urllib.parse.urlparse(self.path)
        q = urllib.parse.parse_qs(url.query)
        nxt = available() + 1
        first = max(1, nxt - args.buffer)
        held = observations[first - 1:nxt - 1]
        if url.path.endswith("/current"):
            # the latest value of every item, however old (agents keep them beside the buffer)
            latest = {}
            for o in observations[:nxt - 1]:
                latest[(o[1], o[2])] = o
            return self.answer(200, streams(first, nxt, sorted(latest.values())))
        if url.path.endswith("/sample"):
            frm = int(q["from"][0]) if "from" in q else first
            count = int(q.get("count", ["100"])[0])
            if frm < first or frm > nxt:
                return self.answer(404, error("OUT_OF_RANGE", "'from' must be between %d and %d" % (first, nxt)))
            chosen = observations[frm - 1:min(nxt - 1, frm - 1 + count)]
            end = chosen[-1][0] + 1 if chosen else frm
            return self.answer(200, streams(first, end, chosen))
        self.answer(404, error("UNSUPPORTED", "no such request: " + url.path))


server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Agent)
with open(args.port_file, "w") as f:
    f.write(str(server.server_address[1]))
server.serve_forever()
