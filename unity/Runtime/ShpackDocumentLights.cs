// ShpackDocumentLights.cs - the lights of a `convert` document: "sun" (null when none was
// found, absent without --extract-sun) and a "lights" array with the same fields, if there is
// one. The SH of such a document has the lights taken out, so each must be added back exactly
// once: an entry of "lights" equal to the sun (same direction and irradiance) is the sun
// listed again and is skipped.
using System.Collections.Generic;
using Newtonsoft.Json.Linq;

namespace Shpack
{
    static class ShpackDocumentLights
    {
        public static List<ShpackLight> Read(JObject doc, ShpackJsonPath at)
        {
            var lights = new List<ShpackLight>();
            JToken sun;
            if (doc.TryGetValue("sun", out sun) && sun.Type != JTokenType.Null)
                lights.Add(ReadLight(at.Object(sun, "/sun"), at, "/sun"));
            JToken list;
            if (!doc.TryGetValue("lights", out list)) return lights;
            JArray items = at.Array(list, "/lights");
            for (int k = 0; k < items.Count; ++k)
            {
                ShpackLight light = ReadLight(at.Object(items[k], "/lights/" + k), at, "/lights/" + k);
                if (!lights.Exists(l => l.SameAs(light))) lights.Add(light);
            }
            return lights;
        }

        static ShpackLight ReadLight(JObject light, ShpackJsonPath at, string pointer)
        {
            string unityAt = pointer + "/unity_light";
            JObject unity = at.Object(at.Member(light, "unity_light", pointer), unityAt);
            return new ShpackLight
            {
                Direction = at.Numbers(at.Member(light, "direction", pointer), 3, pointer + "/direction"),
                Irradiance = at.Numbers(at.Member(light, "irradiance", pointer), 3, pointer + "/irradiance"),
                Quaternion = at.Numbers(at.Member(unity, "quaternion", unityAt), 4, unityAt + "/quaternion"),
                Color = at.Numbers(at.Member(unity, "color", unityAt), 3, unityAt + "/color"),
                ColorSrgb = at.Numbers(at.Member(unity, "color_srgb", unityAt), 3, unityAt + "/color_srgb"),
                Intensity = at.Number(at.Member(unity, "intensity", unityAt), unityAt + "/intensity"),
            };
        }
    }
}
