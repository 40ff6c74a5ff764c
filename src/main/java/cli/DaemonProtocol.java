package cli;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/**
 * What the render daemon and its client say to each other over the daemon's Unix domain socket.
 *
 * <ul>
 *   <li>The client sends one request: its length, then the protocol's magic number, the kind (render or stop),
 *       the client's working folder, whether a person watches its terminal, and the command's arguments.
 *   <li>The daemon answers with frames: a kind byte ({@link #RUNNING}, always the first; {@link #OUT}, {@link #ERR};
 *       {@link #EXIT}, always the last), a length, and the bytes (none for {@link #RUNNING}, UTF-8 text for stdout and
 *       stderr, the exit code for {@link #EXIT}).
 *   <li>While the command runs, one byte {@link #CANCEL} from the client, or its end of the connection, cancels it.
 * </ul>
 *
 * <p>Reads and writes go straight to the channel (not through its streams, which share one lock between reading
 * and writing), so one thread can wait for the client's cancel while another writes the command's output.
 */
final class DaemonProtocol {
    /** "RTD1": a raytracer daemon, version 1 of this protocol. */
    static final int MAGIC = 0x52544431;
    /** A frame of the command's stdout. */
    static final byte OUT = 1;
    /** A frame of the command's stderr. */
    static final byte ERR = 2;
    /** The last frame: the command's exit code. */
    static final byte EXIT = 3;
    /** From the client: cancel the command. */
    static final byte CANCEL = 4;
    /** The first frame: the daemon has taken the request and runs it (until then, the client waits its turn). */
    static final byte RUNNING = 5;
    /** The longest message either side reads: a request (arguments and folder), or a frame's bytes. */
    static final int MAX_MESSAGE_BYTES = 1 << 20;

    private DaemonProtocol() {}

    /** What a client asks: run a render command, or stop the daemon. */
    enum Kind {
        RENDER,
        STOP
    }

    /**
     * One request.
     *
     * @param kind render or stop
     * @param workingFolder the client's working folder, which must be the daemon's
     * @param interactive whether a person watches the client's terminal
     * @param args the command's arguments ({@code render ...})
     */
    record Request(Kind kind, String workingFolder, boolean interactive, List<String> args) {
        void send(SocketChannel channel) throws IOException {
            ByteArrayOutputStream bytes = new ByteArrayOutputStream();
            DataOutputStream data = new DataOutputStream(bytes);
            data.writeInt(MAGIC);
            data.writeByte(kind.ordinal());
            writeString(data, workingFolder);
            data.writeBoolean(interactive);
            data.writeInt(args.size());
            for (String arg : args) writeString(data, arg);
            byte[] body = bytes.toByteArray();
            if (body.length > MAX_MESSAGE_BYTES) {
                throw new IOException("the command's arguments take " + body.length
                        + " bytes; the daemon reads at most " + MAX_MESSAGE_BYTES);
            }
            writeFully(
                    channel,
                    ByteBuffer.allocate(4 + body.length)
                            .putInt(body.length)
                            .put(body)
                            .flip());
        }

        static Request receive(SocketChannel channel) throws IOException {
            int length = readFully(channel, 4).getInt();
            if (length < 0 || length > MAX_MESSAGE_BYTES) throw new IOException("not a request: length " + length);
            DataInputStream data = new DataInputStream(
                    new ByteArrayInputStream(readFully(channel, length).array()));
            if (data.readInt() != MAGIC) throw new IOException("not a request of this daemon's protocol");
            int kind = data.readUnsignedByte();
            if (kind >= Kind.values().length) throw new IOException("unknown request kind " + kind);
            String folder = readString(data);
            boolean interactive = data.readBoolean();
            int count = data.readInt();
            if (count < 0 || count > length) throw new IOException("not a request: " + count + " arguments");
            List<String> args = new ArrayList<>(count);
            for (int i = 0; i < count; i++) args.add(readString(data));
            return new Request(Kind.values()[kind], folder, interactive, args);
        }
    }

    /**
     * One frame of the daemon's answer.
     *
     * @param kind {@link #RUNNING}, {@link #OUT}, {@link #ERR} or {@link #EXIT}
     * @param body its bytes
     */
    record Frame(byte kind, ByteBuffer body) {}

    /** Reads the next frame of the daemon's answer. */
    static Frame readFrame(SocketChannel channel) throws IOException {
        ByteBuffer header = readFully(channel, 5);
        byte kind = header.get();
        int length = header.getInt();
        if (length < 0 || length > MAX_MESSAGE_BYTES) throw new IOException("not a frame: length " + length);
        return new Frame(kind, readFully(channel, length));
    }

    /** Writes frames of one kind: an output stream whose every write is one frame. */
    static OutputStream frames(SocketChannel channel, byte kind) {
        return new OutputStream() {
            @Override
            public void write(int b) throws IOException {
                write(new byte[] {(byte) b}, 0, 1);
            }

            @Override
            public void write(byte[] b, int off, int len) throws IOException {
                if (len == 0) return;
                ByteBuffer frame = ByteBuffer.allocate(5 + len)
                        .put(kind)
                        .putInt(len)
                        .put(b, off, len)
                        .flip();
                synchronized (channel) { // frames from several threads never interleave
                    writeFully(channel, frame);
                }
            }
        };
    }

    /** Writes the first frame: the request is running. */
    static void running(SocketChannel channel) throws IOException {
        synchronized (channel) {
            writeFully(channel, ByteBuffer.allocate(5).put(RUNNING).putInt(0).flip());
        }
    }

    /** Writes the last frame, the exit code. */
    static void exit(SocketChannel channel, int code) throws IOException {
        synchronized (channel) {
            writeFully(
                    channel,
                    ByteBuffer.allocate(9).put(EXIT).putInt(4).putInt(code).flip());
        }
    }

    static void writeFully(SocketChannel channel, ByteBuffer buffer) throws IOException {
        while (buffer.hasRemaining()) channel.write(buffer);
    }

    /** Reads exactly {@code n} bytes; an end of stream before them is an {@link EOFException}. */
    static ByteBuffer readFully(SocketChannel channel, int n) throws IOException {
        ByteBuffer buffer = ByteBuffer.allocate(n);
        while (buffer.hasRemaining()) {
            if (channel.read(buffer) < 0) throw new EOFException("the connection closed");
        }
        return buffer.flip();
    }

    private static void writeString(DataOutputStream data, String s) throws IOException {
        byte[] utf8 = s.getBytes(StandardCharsets.UTF_8);
        data.writeInt(utf8.length);
        data.write(utf8);
    }

    private static String readString(DataInputStream data) throws IOException {
        int n = data.readInt();
        if (n < 0 || n > data.available()) throw new IOException("not a request: a string of " + n + " bytes");
        return new String(data.readNBytes(n), StandardCharsets.UTF_8);
    }
}
