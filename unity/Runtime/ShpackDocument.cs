// ShpackDocument.cs - a shpack JSON document (docs/json-format.md) read back: the output of
// `shpack convert`, or one probe of `shpack bake` ({"probes": [{"position": ..., ...}]}).
//
// Unity's JsonUtility cannot read nested arrays ([[9 R], [9 G], [9 B]]), so this has its own
// small reader (ShpackJson). Numbers are parsed as doubles with the invariant culture; a
// float of the document is written as the double of equal value, so the cast gives back the
// exact float shpack computed.
using System;
using System.Collections.Generic;
using System.IO;
using UnityEngine;
using UnityEngine.Rendering;

namespace Shpack
{
    public sealed class ShpackProbeData
    {
        public Vector3 Position;    // (0, 0, 0) for a convert document
        public double[] RadianceSh; // 27, channel-major
        public float[] UnitySh;     // 27, sh[c, i] at 9c + i
        public float[] Shader;      // 28: unity_SHAr .. unity_SHC

        public SphericalHarmonicsL2 ToSphericalHarmonicsL2() { return ShpackProbe.FromFloats(UnitySh); }
    }

    public static class ShpackDocument
    {
        public const int SchemaVersion = 1;
        static readonly string[] ShaderKeys = { "unity_SHAr", "unity_SHAg", "unity_SHAb", "unity_SHBr", "unity_SHBg", "unity_SHBb", "unity_SHC" };

        public static List<ShpackProbeData> ReadFile(string path)
        {
            return Read(File.ReadAllText(path), path);
        }

        // The probes of a document: one for `convert`, each of "probes" for `bake`. Errors
        // (FormatException) name `source` and the JSON pointer of the value.
        public static List<ShpackProbeData> Read(string text, string source)
        {
            object root = ShpackJson.Parse(text, source);
            var doc = Expect<Dictionary<string, object>>(root, source, "");
            var probes = new List<ShpackProbeData>();
            object list;
            if (doc.TryGetValue("probes", out list))
            {
                var items = Expect<List<object>>(list, source, "/probes");
                for (int k = 0; k < items.Count; ++k)
                    probes.Add(ReadProbe(Expect<Dictionary<string, object>>(items[k], source, "/probes/" + k), source, "/probes/" + k));
                return probes;
            }
            double version = Number(Member(doc, "schema_version", source, ""), source, "/schema_version");
            if (version != SchemaVersion)
                throw new FormatException(source + ": /schema_version: unsupported schema version " + version);
            probes.Add(ReadProbe(doc, source, ""));
            return probes;
        }

        static ShpackProbeData ReadProbe(Dictionary<string, object> probe, string source, string pointer)
        {
            var data = new ShpackProbeData { RadianceSh = new double[27], UnitySh = new float[27], Shader = new float[28] };
            object position;
            if (probe.TryGetValue("position", out position))
            {
                var p = Array(position, 3, source, pointer + "/position");
                data.Position = new Vector3((float)Number(p[0], source, pointer + "/position/0"),
                                            (float)Number(p[1], source, pointer + "/position/1"),
                                            (float)Number(p[2], source, pointer + "/position/2"));
            }
            var radiance = Array(Member(probe, "radiance_sh", source, pointer), 3, source, pointer + "/radiance_sh");
            var unity = Array(Member(probe, "sphericalHarmonicsL2", source, pointer), 3, source, pointer + "/sphericalHarmonicsL2");
            for (int c = 0; c < 3; ++c)
            {
                var r = Array(radiance[c], 9, source, pointer + "/radiance_sh/" + c);
                var u = Array(unity[c], 9, source, pointer + "/sphericalHarmonicsL2/" + c);
                for (int i = 0; i < 9; ++i)
                {
                    data.RadianceSh[9 * c + i] = Number(r[i], source, pointer + "/radiance_sh/" + c + "/" + i);
                    data.UnitySh[9 * c + i] = Float(u[i], source, pointer + "/sphericalHarmonicsL2/" + c + "/" + i);
                }
            }
            var shader = Expect<Dictionary<string, object>>(Member(probe, "shader", source, pointer), source, pointer + "/shader");
            for (int v = 0; v < 7; ++v)
            {
                string at = pointer + "/shader/" + ShaderKeys[v];
                var vector = Array(Member(shader, ShaderKeys[v], source, pointer + "/shader"), 4, source, at);
                for (int k = 0; k < 4; ++k) data.Shader[4 * v + k] = Float(vector[k], source, at + "/" + k);
            }
            return data;
        }

        static T Expect<T>(object value, string source, string pointer) where T : class
        {
            var typed = value as T;
            if (typed == null)
                throw new FormatException(source + ": " + (pointer.Length == 0 ? "/" : pointer) + ": expected " +
                                          (typeof(T) == typeof(List<object>) ? "an array" : "an object"));
            return typed;
        }

        static object Member(Dictionary<string, object> obj, string key, string source, string pointer)
        {
            object value;
            if (!obj.TryGetValue(key, out value))
                throw new FormatException(source + ": " + (pointer.Length == 0 ? "/" : pointer) + ": missing key \"" + key + "\"");
            return value;
        }

        static List<object> Array(object value, int count, string source, string pointer)
        {
            var list = value as List<object>;
            if (list == null || list.Count != count)
                throw new FormatException(source + ": " + pointer + ": expected an array of " + count + " elements");
            return list;
        }

        static double Number(object value, string source, string pointer)
        {
            if (!(value is double)) throw new FormatException(source + ": " + pointer + ": expected a number");
            double d = (double)value;
            if (double.IsNaN(d) || double.IsInfinity(d)) throw new FormatException(source + ": " + pointer + ": expected a finite number");
            return d;
        }

        static float Float(object value, string source, string pointer)
        {
            float f = (float)Number(value, source, pointer);
            if (float.IsInfinity(f)) throw new FormatException(source + ": " + pointer + ": out of float32 range");
            return f;
        }
    }
}
