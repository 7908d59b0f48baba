// SPDX-License-Identifier: MIT
// Every public member of the binding has an XML doc comment (the compiler's CS1591 check,
// made an error in Frusta.Binding.csproj, is repeated here on the built documentation).
using System;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Xml.Linq;
using Frusta.Binding;
using Xunit;

namespace Frusta.Binding.Tests
{
    public class DocsTests
    {
        static string Id(MemberInfo m)
        {
            static string TypeName(Type t) => t.IsGenericType
                ? $"{t.Namespace}.{t.Name.Substring(0, t.Name.IndexOf('`'))}{{{string.Join(",", t.GetGenericArguments().Select(TypeName))}}}"
                : (t.IsByRef ? TypeName(t.GetElementType()) + "@" : (t.FullName ?? t.Name).Replace('+', '.'));
            string Params(MethodBase b)
            {
                var p = b.GetParameters();
                return p.Length == 0 ? "" : "(" + string.Join(",", p.Select(x => TypeName(x.ParameterType))) + ")";
            }
            string owner = m.DeclaringType?.FullName?.Replace('+', '.');
            return m switch
            {
                Type t => "T:" + t.FullName.Replace('+', '.'),
                ConstructorInfo c => $"M:{owner}.#ctor{Params(c)}",
                MethodInfo mi when mi.Name.StartsWith("op_") => $"M:{owner}.{mi.Name}{Params(mi)}" + (mi.Name is "op_Implicit" or "op_Explicit" ? "~" + TypeName(mi.ReturnType) : ""),
                MethodInfo mi => $"M:{owner}.{mi.Name}{Params(mi)}",
                PropertyInfo p => $"P:{owner}.{p.Name}",
                FieldInfo f => $"F:{owner}.{f.Name}",
                EventInfo e => $"E:{owner}.{e.Name}",
                _ => throw new NotSupportedException(m.ToString()),
            };
        }

        [Fact]
        public void EveryPublicMemberOfTheBindingIsDocumented()
        {
            Assembly binding = typeof(World).Assembly;
            string xml = Path.ChangeExtension(binding.Location, ".xml");
            Assert.True(File.Exists(xml), $"{xml} missing: GenerateDocumentationFile is off");
            var documented = XDocument.Load(xml).Descendants("member")
                .Where(e => e.Elements().Any(c => c.Name == "summary" && !string.IsNullOrWhiteSpace(c.Value)))
                .Select(e => e.Attribute("name").Value).ToHashSet();
            var missing = binding.GetExportedTypes().Where(t => !t.Name.Contains('<')) // fixed buffers' generated types
                .SelectMany(t => t.GetMembers(BindingFlags.Public | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly)
                    .Where(m => !(m is MethodInfo mi && mi.IsSpecialName && !mi.Name.StartsWith("op_")))  // accessors
                    .Where(m => !(t.IsEnum && m.Name == "value__") && !m.Name.Contains('<'))
                    .Where(m => !(m is ConstructorInfo && t.IsValueType && ((ConstructorInfo)m).GetParameters().Length == 0))
                    .Where(m => !(m is MethodInfo o && o.GetBaseDefinition().DeclaringType != o.DeclaringType && o.DeclaringType != typeof(object)
                                  && documented.Contains(Id(m))))
                    .Prepend(t))
                .Select(Id).Where(id => !documented.Contains(id)).Distinct().ToList();
            Assert.True(missing.Count == 0, "undocumented:\n" + string.Join("\n", missing));
            Assert.True(documented.Count > 200, $"{documented.Count} documented members");
        }
    }
}
