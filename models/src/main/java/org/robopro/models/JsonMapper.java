package org.robopro.models;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.databind.JsonSerializer;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.SerializerProvider;
import com.fasterxml.jackson.databind.module.SimpleModule;
import java.io.IOException;

/**
 * The Jackson mapper for robopro's JSON outputs (summaries, reports, demo files): indented, and a
 * number that is not finite (NaN, infinity: "no value") is written as {@code null}, since JSON has
 * no NaN and Jackson would otherwise write one that other readers refuse or misread.
 */
public final class JsonMapper {
    private JsonMapper() { }

    /** A new indented mapper writing non-finite numbers as null. */
    public static ObjectMapper create() {
        SimpleModule finite = new SimpleModule("robopro-finite-numbers");
        JsonSerializer<Double> d = new JsonSerializer<>() {
            @Override
            public void serialize(Double v, JsonGenerator g, SerializerProvider p) throws IOException {
                if (v == null || !Double.isFinite(v)) g.writeNull();
                else g.writeNumber(v);
            }
        };
        JsonSerializer<Float> f = new JsonSerializer<>() {
            @Override
            public void serialize(Float v, JsonGenerator g, SerializerProvider p) throws IOException {
                if (v == null || !Float.isFinite(v)) g.writeNull();
                else g.writeNumber(v);
            }
        };
        finite.addSerializer(Double.class, d);
        finite.addSerializer(double.class, d);
        finite.addSerializer(Float.class, f);
        finite.addSerializer(float.class, f);
        finite.addSerializer(double[].class, new JsonSerializer<>() {
            @Override
            public void serialize(double[] v, JsonGenerator g, SerializerProvider p) throws IOException {
                g.writeStartArray();
                for (double x : v) {
                    if (Double.isFinite(x)) g.writeNumber(x);
                    else g.writeNull();
                }
                g.writeEndArray();
            }
        });
        return new ObjectMapper().registerModule(finite).enable(SerializationFeature.INDENT_OUTPUT);
    }
}
