using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using YamlDotNet.RepresentationModel;

namespace HeadGait.Tooling
{
    /// <summary>One object of a Unity YAML file: the `--- !u!CLASS &amp;FILEID [stripped]` header and its parsed body.</summary>
    public sealed class UnityObject
    {
        public int ClassId;
        public long FileId;
        public bool Stripped;
        public string Type;
        public YamlMappingNode Body;

        public string Scalar(string key) => Body.Children.TryGetValue(new YamlScalarNode(key), out var n) && n is YamlScalarNode s ? s.Value ?? "" : null;
        public YamlNode Node(string key) => Body.Children.TryGetValue(new YamlScalarNode(key), out var n) ? n : null;
    }

    /// <summary>
    /// Unity's text assets are YAML streams whose documents carry tags (`--- !u!74 &amp;7400000`, class ID and local fileID)
    /// and may be `stripped` (a prefab instance's object, holding only its link to the source), which YAML parsers reject.
    /// The file is split on those headers first, then each body is parsed with YamlDotNet.
    /// </summary>
    public static class UnityYamlFile
    {
        static readonly Regex Header = new Regex(@"^--- !u!(\d+) &(-?\d+)( stripped)?\s*$", RegexOptions.Multiline);

        public static List<UnityObject> Parse(string text, string file)
        {
            text = text.Replace("\r\n", "\n");
            var matches = Header.Matches(text);
            if (matches.Count == 0) throw new FormatException($"{file}: no '--- !u!CLASS &ID' document");
            var list = new List<UnityObject>();
            for (int i = 0; i < matches.Count; i++)
            {
                var m = matches[i];
                int start = m.Index + m.Length;
                int end = i + 1 < matches.Count ? matches[i + 1].Index : text.Length;
                var stream = new YamlStream();
                try
                {
                    stream.Load(new StringReader(text.Substring(start, end - start)));
                }
                catch (YamlDotNet.Core.YamlException e)
                {
                    throw new FormatException($"{file}: document &{m.Groups[2].Value} is not valid YAML ({e.Message})");
                }
                if (stream.Documents.Count != 1 || !(stream.Documents[0].RootNode is YamlMappingNode root) || root.Children.Count != 1)
                    throw new FormatException($"{file}: document &{m.Groups[2].Value} is not one 'Type:' mapping");
                var entry = root.Children.First();
                list.Add(new UnityObject
                {
                    ClassId = int.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture),
                    FileId = long.Parse(m.Groups[2].Value, CultureInfo.InvariantCulture),
                    Stripped = m.Groups[3].Success,
                    Type = ((YamlScalarNode)entry.Key).Value,
                    Body = entry.Value as YamlMappingNode ?? new YamlMappingNode(),
                });
            }
            return list;
        }
    }
}
