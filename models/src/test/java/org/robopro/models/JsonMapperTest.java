package org.robopro.models;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class JsonMapperTest {
    @Test
    void nonFiniteNumbers_areWrittenAsNull_andTheOutputIsStrictJson() throws Exception {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("sigma", Double.NaN);
        m.put("max", Double.POSITIVE_INFINITY);
        m.put("ok", 1.5);
        m.put("list", List.of(2.0, Double.NaN));
        m.put("array", new double[] {Double.NEGATIVE_INFINITY, 3});
        m.put("f", Float.NaN);
        String text = JsonMapper.create().writeValueAsString(m);
        assertFalse(text.contains("NaN") || text.contains("Infinity"), text);
        JsonNode n = new ObjectMapper().readTree(text); // strict reader: no NaN allowed
        assertTrue(n.get("sigma").isNull());
        assertTrue(n.get("max").isNull());
        assertEquals(1.5, n.get("ok").asDouble());
        assertTrue(n.get("list").get(1).isNull());
        assertTrue(n.get("array").get(0).isNull());
        assertEquals(3, n.get("array").get(1).asDouble());
        assertTrue(n.get("f").isNull());
    }
}
