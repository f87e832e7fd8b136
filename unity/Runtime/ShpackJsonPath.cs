// ShpackJsonPath.cs - typed access to the Json.NET tokens of a shpack document: each accessor
// returns the value in the shape asked for, or throws a FormatException naming the file and
// the JSON pointer of the value (e.g. "sky.json: /shader: missing key \"unity_SHC\"").
using System;
using Newtonsoft.Json.Linq;

namespace Shpack
{
    sealed class ShpackJsonPath
    {
        readonly string source;

        public ShpackJsonPath(string source) { this.source = source; }

        public FormatException Error(string pointer, string problem)
        {
            return new FormatException(source + ": " + (pointer.Length == 0 ? "/" : pointer) + ": " + problem);
        }

        public JObject Object(JToken value, string pointer)
        {
            var obj = value as JObject;
            if (obj == null) throw Error(pointer, "expected an object");
            return obj;
        }

        public JToken Member(JObject obj, string key, string pointer)
        {
            JToken value;
            if (!obj.TryGetValue(key, out value)) throw Error(pointer, "missing key \"" + key + "\"");
            return value;
        }

        public JArray Array(JToken value, string pointer)
        {
            var list = value as JArray;
            if (list == null) throw Error(pointer, "expected an array");
            return list;
        }

        public JArray Array(JToken value, int count, string pointer)
        {
            var list = value as JArray;
            if (list == null || list.Count != count) throw Error(pointer, "expected an array of " + count + " elements");
            return list;
        }

        public double Number(JToken value, string pointer)
        {
            if (value == null || (value.Type != JTokenType.Float && value.Type != JTokenType.Integer))
                throw Error(pointer, "expected a number");
            double d = value.Value<double>();
            if (double.IsNaN(d) || double.IsInfinity(d)) throw Error(pointer, "expected a finite number");
            return d;
        }

        public double[] Numbers(JToken value, int count, string pointer)
        {
            JArray list = Array(value, count, pointer);
            var numbers = new double[count];
            for (int k = 0; k < count; ++k) numbers[k] = Number(list[k], pointer + "/" + k);
            return numbers;
        }

        public float[] Floats(JToken value, int count, string pointer)
        {
            double[] numbers = Numbers(value, count, pointer);
            var floats = new float[count];
            for (int k = 0; k < count; ++k)
            {
                floats[k] = (float)numbers[k];
                if (float.IsInfinity(floats[k])) throw Error(pointer + "/" + k, "out of float32 range");
            }
            return floats;
        }
    }
}
