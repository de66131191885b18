package org.robopro.comms;

/** A program held by the controller: its name, length in bytes and CRC-32 of its bytes. */
public record ProgramInfo(String name, int length, long crc32) { }
