// ShpackDocument.cs - a shpack JSON document (docs/json-format.md) read back: the output of
// `shpack convert`, or the probes of `shpack bake` ({"probes": [{"position": ..., ...}]}),
// through Newtonsoft Json.NET (com.unity.nuget.newtonsoft-json), since Unity's JsonUtility
// cannot read nested arrays ([[9 R], [9 G], [9 B]]).
//
// Numbers are read as doubles (FloatParseHandling.Double): a float of the document is
// written as the double of equal value, so the cast gives back the exact float shpack
// computed. A value of the wrong shape is a FormatException naming the file and the JSON
// pointer of the value.
using System;
using System.Collections.Generic;
using System.IO;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;
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

    // What a document holds: its probes, and the lights taken out of its map ("sun", then
    // each of "lights" that is not the sun again), each to be added once.
    public sealed class ShpackDocumentData
    {
        public List<ShpackProbeData> Probes = new List<ShpackProbeData>();
        public List<ShpackLight> Lights = new List<ShpackLight>();
    }

    public static class ShpackDocument
    {
        public const int SchemaVersion = 1;
        static readonly string[] ShaderKeys = { "unity_SHAr", "unity_SHAg", "unity_SHAb", "unity_SHBr", "unity_SHBg", "unity_SHBb", "unity_SHC" };

        public static List<ShpackProbeData> ReadFile(string path)
        {
            return LoadFile(path).Probes;
        }

        public static ShpackDocumentData LoadFile(string path)
        {
            return Load(File.ReadAllText(path), path);
        }

        // The probes of a document (one for `convert`, each of "probes" for `bake`) and its lights.
        public static ShpackDocumentData Load(string text, string source)
        {
            var at = new ShpackJsonPath(source);
            JObject doc = at.Object(Parse(text, source), "");
            var data = new ShpackDocumentData();
            JToken list;
            if (doc.TryGetValue("probes", out list))
            {
                JArray items = at.Array(list, "/probes");
                for (int k = 0; k < items.Count; ++k)
                    data.Probes.Add(ReadProbe(at.Object(items[k], "/probes/" + k), at, "/probes/" + k));
                return data;
            }
            double version = at.Number(at.Member(doc, "schema_version", ""), "/schema_version");
            if (version != SchemaVersion)
                throw new FormatException(source + ": /schema_version: unsupported schema version " + version);
            data.Probes.Add(ReadProbe(doc, at, ""));
            data.Lights = ShpackDocumentLights.Read(doc, at);
            return data;
        }

        // Strict JSON: numbers as doubles, dates left as strings, nothing after the document.
        static JToken Parse(string text, string source)
        {
            try
            {
                using (var reader = new JsonTextReader(new StringReader(text)))
                {
                    reader.FloatParseHandling = FloatParseHandling.Double;
                    reader.DateParseHandling = DateParseHandling.None;
                    JToken root = JToken.ReadFrom(reader);
                    if (reader.Read()) throw new JsonReaderException("unexpected text after the document");
                    return root;
                }
            }
            catch (JsonReaderException e)
            {
                throw new FormatException(source + ": not valid JSON: " + e.Message, e);
            }
        }

        static ShpackProbeData ReadProbe(JObject probe, ShpackJsonPath at, string pointer)
        {
            var data = new ShpackProbeData { RadianceSh = new double[27], UnitySh = new float[27], Shader = new float[28] };
            JToken position;
            if (probe.TryGetValue("position", out position))
            {
                double[] p = at.Numbers(position, 3, pointer + "/position");
                data.Position = new Vector3((float)p[0], (float)p[1], (float)p[2]);
            }
            JArray radiance = at.Array(at.Member(probe, "radiance_sh", pointer), 3, pointer + "/radiance_sh");
            JArray unity = at.Array(at.Member(probe, "sphericalHarmonicsL2", pointer), 3, pointer + "/sphericalHarmonicsL2");
            for (int c = 0; c < 3; ++c)
            {
                double[] r = at.Numbers(radiance[c], 9, pointer + "/radiance_sh/" + c);
                float[] u = at.Floats(unity[c], 9, pointer + "/sphericalHarmonicsL2/" + c);
                System.Array.Copy(r, 0, data.RadianceSh, 9 * c, 9);
                System.Array.Copy(u, 0, data.UnitySh, 9 * c, 9);
            }
            JObject shader = at.Object(at.Member(probe, "shader", pointer), pointer + "/shader");
            for (int v = 0; v < 7; ++v)
            {
                float[] vector = at.Floats(at.Member(shader, ShaderKeys[v], pointer + "/shader"), 4, pointer + "/shader/" + ShaderKeys[v]);
                System.Array.Copy(vector, 0, data.Shader, 4 * v, 4);
            }
            return data;
        }
    }
}
