/**
 * The controller link: commands, protocol client, connection, simulated controller. The serial
 * framing ({@code org.robopro.comms.link}) is internal.
 */
module org.robopro.comms {
    requires transitive org.robopro.programs;
    requires org.robopro.world;  // the simulated controller's truth
    requires com.fazecast.jSerialComm;
    requires org.slf4j;

    exports org.robopro.comms;
    exports org.robopro.comms.client;
    exports org.robopro.comms.connection;
    exports org.robopro.comms.protocol;
    exports org.robopro.comms.sim;
}
