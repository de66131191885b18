package org.robopro.comms.link;

import com.fazecast.jSerialComm.SerialPort;
import com.fazecast.jSerialComm.SerialPortDataListener;
import com.fazecast.jSerialComm.SerialPortEvent;
import java.io.IOException;
import java.util.concurrent.atomic.AtomicBoolean;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A serial port through jSerialComm, 8N1 without flow control. Opened by path
 * ({@code SerialPort.getCommPort("/tmp/ttyA")}: pseudo-terminals are not listed by
 * getCommPorts()). jSerialComm may report PORT_DISCONNECTED over and over once a device is
 * gone; the listener reacts to the first event only, then removes itself and closes the port.
 */
public final class SerialPortByteLink implements ByteLink {
    private static final Logger LOG = LoggerFactory.getLogger(SerialPortByteLink.class);

    private final SerialPort port;
    private final String path;
    private final AtomicBoolean closed = new AtomicBoolean();

    public SerialPortByteLink(String path, int baud) throws IOException {
        this.path = path;
        this.port = SerialPort.getCommPort(path);
        port.setComPortParameters(baud, 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY);
        port.setFlowControl(SerialPort.FLOW_CONTROL_DISABLED);
        port.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING | SerialPort.TIMEOUT_WRITE_BLOCKING, 50, 1000);
        if (!port.openPort())
            throw new IOException("cannot open serial port " + path + " (jSerialComm error " + port.getLastErrorCode()
                    + " at " + port.getLastErrorLocation() + ")");
        port.addDataListener(new SerialPortDataListener() {
            @Override public int getListeningEvents() { return SerialPort.LISTENING_EVENT_PORT_DISCONNECTED; }

            @Override public void serialEvent(SerialPortEvent event) {
                if (event.getEventType() == SerialPort.LISTENING_EVENT_PORT_DISCONNECTED && closed.compareAndSet(false, true)) {
                    LOG.warn("serial port {} disconnected", path);
                    // Not on the event thread: removeDataListener waits for that thread.
                    Thread t = new Thread(() -> {
                        port.removeDataListener();
                        port.closePort();
                    }, "robopro-serial-close");
                    t.setDaemon(true);
                    t.start();
                }
            }
        });
    }

    @Override
    public int read(byte[] buf) throws IOException {
        if (closed.get()) return -1;
        int n = port.readBytes(buf, buf.length);
        if (n < 0) {
            if (closed.get() || !port.isOpen()) return -1;
            throw new IOException("read from serial port " + path + " failed (jSerialComm error " + port.getLastErrorCode() + ")");
        }
        return n;
    }

    @Override
    public void write(byte[] bytes) throws IOException {
        if (closed.get()) throw new IOException("serial port " + path + " is closed");
        int off = 0;
        while (off < bytes.length) {
            int n = port.writeBytes(bytes, bytes.length - off, off);
            if (n <= 0) throw new IOException("write to serial port " + path + " failed (jSerialComm error " + port.getLastErrorCode() + ")");
            off += n;
        }
    }

    @Override public String describe() { return "serial " + path; }

    @Override
    public void close() {
        if (closed.compareAndSet(false, true)) {
            port.removeDataListener();
            port.closePort();
        }
    }
}
