// ShpackJson.cs - a small, strict JSON reader (RFC 8259) for shpack documents: objects become
// Dictionary<string, object>, arrays List<object>, numbers double, and true/false/null bool
// or null. Errors are FormatException naming the source and the character offset.
using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace Shpack
{
    public static class ShpackJson
    {
        public static object Parse(string text, string source)
        {
            var reader = new Reader { Text = text, Source = source };
            reader.SkipSpace();
            object value = reader.Value(0);
            reader.SkipSpace();
            if (reader.Pos != text.Length) throw reader.Error("unexpected text after the document");
            return value;
        }

        sealed class Reader
        {
            public string Text, Source;
            public int Pos;
            const int MaxDepth = 64;

            public FormatException Error(string problem)
            {
                return new FormatException(Source + ": not valid JSON at offset " + Pos + ": " + problem);
            }

            public void SkipSpace()
            {
                while (Pos < Text.Length && (Text[Pos] == ' ' || Text[Pos] == '\t' || Text[Pos] == '\n' || Text[Pos] == '\r')) ++Pos;
            }

            void Expect(char ch)
            {
                SkipSpace();
                if (Pos >= Text.Length || Text[Pos] != ch) throw Error("expected '" + ch + "'");
                ++Pos;
            }

            static bool IsAsciiDigit(char ch) { return ch >= '0' && ch <= '9'; }

            public object Value(int depth)
            {
                if (depth > MaxDepth) throw Error("nested too deeply");
                SkipSpace();
                if (Pos >= Text.Length) throw Error("unexpected end");
                char ch = Text[Pos];
                if (ch == '{') return Object(depth);
                if (ch == '[') return Array(depth);
                if (ch == '"') return String();
                if (ch == '-' || (ch >= '0' && ch <= '9')) return Number();
                if (Word("true")) return true;
                if (Word("false")) return false;
                if (Word("null")) return null;
                throw Error("unexpected character '" + ch + "'");
            }

            bool Word(string word)
            {
                if (string.CompareOrdinal(Text, Pos, word, 0, word.Length) != 0) return false;
                Pos += word.Length;
                return true;
            }

            Dictionary<string, object> Object(int depth)
            {
                var obj = new Dictionary<string, object>();
                ++Pos;
                SkipSpace();
                if (Pos < Text.Length && Text[Pos] == '}') { ++Pos; return obj; }
                while (true)
                {
                    SkipSpace();
                    if (Pos >= Text.Length || Text[Pos] != '"') throw Error("expected a key");
                    string key = String();
                    Expect(':');
                    obj[key] = Value(depth + 1);
                    SkipSpace();
                    if (Pos < Text.Length && Text[Pos] == ',') { ++Pos; continue; }
                    Expect('}');
                    return obj;
                }
            }

            List<object> Array(int depth)
            {
                var list = new List<object>();
                ++Pos;
                SkipSpace();
                if (Pos < Text.Length && Text[Pos] == ']') { ++Pos; return list; }
                while (true)
                {
                    list.Add(Value(depth + 1));
                    SkipSpace();
                    if (Pos < Text.Length && Text[Pos] == ',') { ++Pos; continue; }
                    Expect(']');
                    return list;
                }
            }

            string String()
            {
                var sb = new StringBuilder();
                ++Pos;  // the opening quote
                while (true)
                {
                    if (Pos >= Text.Length) throw Error("unterminated string");
                    char ch = Text[Pos++];
                    if (ch == '"') return sb.ToString();
                    if (ch < ' ') throw Error("control character in a string");
                    if (ch != '\\') { sb.Append(ch); continue; }
                    if (Pos >= Text.Length) throw Error("unterminated escape");
                    char e = Text[Pos++];
                    switch (e)
                    {
                        case '"': sb.Append('"'); break;
                        case '\\': sb.Append('\\'); break;
                        case '/': sb.Append('/'); break;
                        case 'b': sb.Append('\b'); break;
                        case 'f': sb.Append('\f'); break;
                        case 'n': sb.Append('\n'); break;
                        case 'r': sb.Append('\r'); break;
                        case 't': sb.Append('\t'); break;
                        case 'u':
                            int code;
                            if (Pos + 4 > Text.Length ||
                                !int.TryParse(Text.Substring(Pos, 4), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out code))
                                throw Error("bad \\u escape");
                            sb.Append((char)code);
                            Pos += 4;
                            break;
                        default: throw Error("bad escape");
                    }
                }
            }

            double Number()
            {
                int start = Pos;
                if (Text[Pos] == '-') ++Pos;
                int digits = Pos;
                while (Pos < Text.Length && IsAsciiDigit(Text[Pos])) ++Pos;
                if (Pos == digits) throw Error("expected a digit");
                if (Text[digits] == '0' && Pos - digits > 1) throw Error("leading zero");
                if (Pos < Text.Length && Text[Pos] == '.')
                {
                    ++Pos;
                    int fraction = Pos;
                    while (Pos < Text.Length && IsAsciiDigit(Text[Pos])) ++Pos;
                    if (Pos == fraction) throw Error("expected a digit after '.'");
                }
                if (Pos < Text.Length && (Text[Pos] == 'e' || Text[Pos] == 'E'))
                {
                    ++Pos;
                    if (Pos < Text.Length && (Text[Pos] == '+' || Text[Pos] == '-')) ++Pos;
                    int exponent = Pos;
                    while (Pos < Text.Length && IsAsciiDigit(Text[Pos])) ++Pos;
                    if (Pos == exponent) throw Error("expected a digit in the exponent");
                }
                return double.Parse(Text.Substring(start, Pos - start), NumberStyles.Float, CultureInfo.InvariantCulture);
            }
        }
    }
}
