package org.robopro.comms.protocol;

import com.code_intelligence.jazzer.junit.FuzzTest;

/**
 * Fuzzes the checksum-mode codec: any text either opens or is refused (null), never throws; a
 * sealed request opens to itself, and with any one character changed it never opens.
 * Without JAZZER_FUZZ=1 this runs the seed inputs only (regression mode, part of every build).
 */
class LinkChecksumFuzzTest {
    @FuzzTest(maxDuration = "15s")
    void openAndUnseal_anyText_neverThrow_andDamageIsNeverAccepted(String text) {
        if (text == null) return;
        LinkChecksum.open(text);
        LinkChecksum.unseal(text, "");
        LinkChecksum.key(text);
        LinkChecksum.instruction(text);
        // The wire carries bytes (ISO-8859-1): compare what a byte can hold.
        text = new String(text.getBytes(java.nio.charset.StandardCharsets.ISO_8859_1), java.nio.charset.StandardCharsets.ISO_8859_1);
        String req = OpenAbb.request(OpenAbb.MOVE_JOINTS_TAGGED, text.replace('#', ' ').replace('*', ' ').strip());
        String sealed = LinkChecksum.sealRequest(req);
        if (!req.equals(LinkChecksum.open(sealed))) throw new AssertionError("sealed request does not open: " + sealed);
        for (int i = 0; i < sealed.length(); i++) {
            String damaged = sealed.substring(0, i) + (char) ((sealed.charAt(i) ^ 0x04) & 0xFF) + sealed.substring(i + 1);
            if (LinkChecksum.open(damaged) != null) throw new AssertionError("damaged request accepted: " + damaged);
        }
        String reply = LinkChecksum.seal(text.replace('\n', ' '), LinkChecksum.key(sealed));
        if (LinkChecksum.unseal(reply, LinkChecksum.key(sealed)) == null) throw new AssertionError("sealed reply does not open");
    }
}
