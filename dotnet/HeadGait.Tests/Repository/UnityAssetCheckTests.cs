using System;
using System.IO;
using System.Linq;
using HeadGait.Tooling;
using NUnit.Framework;

namespace HeadGait.Tests
{
    /// <summary>The package's Unity assets (controller, clips, prefabs, sample scene) checked without Unity.</summary>
    public class UnityAssetCheckTests
    {
        static string Package => RepositoryPaths.Package;

        [Test]
        public void ThePackagesAssetsResolveAndAgreeWithTheCore()
        {
            var problems = UnityAssetCheck.Problems(Package);
            Assert.That(problems, Is.Empty, "regenerate with `dotnet run --project dotnet/HeadGait.Cli -c Release -- clips`");
        }

        /// <summary>
        /// The Legs sample's camera is tagged MainCamera, as Unity's new scenes tag theirs: Camera.main finds a camera by that tag
        /// alone, and FollowHead falls back to Camera.main for the head (it found none in this scene when untagged).
        /// </summary>
        [Test]
        public void TheLegsSampleCameraIsTheMainCamera()
        {
            var docs = UnityYamlFile.Parse(File.ReadAllText(Path.Combine(Package, GaitAssetFiles.SampleScene)), GaitAssetFiles.SampleScene);
            var cameras = docs.Where(d => d.ClassId == 1 && d.Scalar("m_Name") == "Main Camera").ToList();
            Assert.That(cameras, Has.Count.EqualTo(1));
            Assert.That(cameras[0].Scalar("m_TagString"), Is.EqualTo("MainCamera"));
        }

        [Test]
        public void TheCommittedAssetsAreWhatTheGeneratorWrites()
        {
            // The clips and controller are generated from the core; edits by hand or a changed phase map must be regenerated.
            string copy = CopyOfPackage();
            try
            {
                GaitAssetFiles.WriteAll(copy, CorrelationTemplate.Load(Path.Combine(copy, GaitAssetFiles.CorTemplate)).PhaseMap);
                foreach (var relative in new[] { GaitAssetFiles.Controller, GaitAssetFiles.ClipPath(LocomotionState.Walking), GaitAssetFiles.HumanoidClipPath(LocomotionState.Walking), GaitAssetFiles.HumanoidController, GaitAssetFiles.LegsPrefab, GaitAssetFiles.MannequinPrefab, GaitAssetFiles.SampleScene, PrimitiveMaterials.ShaderPath, PrimitiveMaterials.Ground.Path })
                    Assert.That(File.ReadAllText(Path.Combine(copy, relative)), Is.EqualTo(File.ReadAllText(Path.Combine(Package, relative))), relative + " is out of date");
            }
            finally
            {
                Directory.Delete(copy, true);
            }
        }

        [Test]
        public void TheCheckFailsOnABrokenCopy()
        {
            string copy = CopyOfPackage();
            try
            {
                Assert.That(UnityAssetCheck.Problems(copy), Is.Empty, "the unbroken copy passes");
                string controller = Path.Combine(copy, GaitAssetFiles.Controller);
                string legs = Path.Combine(copy, GaitAssetFiles.LegsPrefab);
                string scene = Path.Combine(copy, GaitAssetFiles.SampleScene);
                string walking = Path.Combine(copy, GaitAssetFiles.ClipPath(LocomotionState.Walking));
                string legAnimatorGuid = GaitAssetFiles.GuidOf(copy, GaitAssetFiles.GaitLegAnimatorScript);
                string imuGuid = GaitAssetFiles.GuidOf(copy, GaitAssetFiles.HeadImuSourceScript);
                string corGuid = GaitAssetFiles.GuidOf(copy, GaitAssetFiles.CorTemplate);

                // A parameter renamed, a transition's target state gone, a script pointing at the wrong class, a GUID to
                // nothing, and a walking clip timed with Perry's map instead of the trained one.
                Edit(controller, t => t.Replace("m_TimeParameter: " + AnimatorParameters.StridePhase, "m_TimeParameter: Stride").Replace("- m_Name: " + AnimatorParameters.StridePhase, "- m_Name: Stride"));
                long walkingState = GaitControllerYaml.StateId(LocomotionState.Walking);
                Edit(controller, t => t.Replace($"--- !u!1102 &{walkingState}\n", "--- !u!1102 &12345\n"));
                Edit(legs, t => ReplaceFirst(t, "guid: " + legAnimatorGuid, "guid: " + imuGuid));
                Edit(legs, t => t.Replace(corGuid, "0123456789abcdef0123456789abcdef"));
                Edit(scene, t => t.Replace("m_PrefabInstance: {fileID: " + SampleSceneYaml.PrefabInstanceId + "}", "m_PrefabInstance: {fileID: 42}"));
                File.WriteAllText(walking, GaitClipYaml.Write(new GaitClips(PhaseMap.Perry), LocomotionState.Walking));
                File.WriteAllText(Path.Combine(copy, GaitAssetFiles.HumanoidClipPath(LocomotionState.StartWalkRight)), HumanoidClipYaml.Write(new GaitClips(PhaseMap.Perry), LocomotionState.StartWalkRight));
                Edit(Path.Combine(copy, GaitAssetFiles.HumanoidClipPath(LocomotionState.Standing)), t => t.Replace("m_Name: Standing", "m_Name: Idle"));
                string misnamed = Path.Combine(copy, "Runtime", "Components", "Misnamed.cs");
                File.WriteAllText(misnamed, "class SomethingElse {}");
                File.WriteAllText(misnamed + ".meta", UnityMeta.Text(misnamed, "abcdefabcdefabcdefabcdefabcdefab"));
                string playerGuid = GaitAssetFiles.GuidOf(copy, GaitAssetFiles.RecordingPlayerScript);
                Edit(scene, t => t.Replace("guid: " + playerGuid, "guid: abcdefabcdefabcdefabcdefabcdefab"));

                // The study scene's humanoid (a prefab instance) no longer listed under its parent, and the block avatar's
                // FollowHead with a field the script does not have.
                string study = StudyScene.PathIn(copy);
                var studyScene = File.ReadAllText(study);
                long instanceRoot = long.Parse(System.Text.RegularExpressions.Regex.Match(studyScene, @"--- !u!4 &(\d+) stripped").Groups[1].Value);
                Edit(study, t => t.Replace("  m_Children:\n  - {fileID: " + instanceRoot + "}\n", "  m_Children: []\n"));
                Edit(study, t => t.Replace("  positionSmoothing: 0\n", "  positionLag: 0\n"));
                long legsRoot = UnityHierarchyYaml.Id(GaitAssetFiles.LegsRoot, "", "Transform");
                long avatar = UnityHierarchyYaml.Id(GaitAssetFiles.LegsRoot, GaitAssetFiles.AvatarName, "Transform");
                Edit(study, t => t.Replace("m_CorrespondingSourceObject: {fileID: " + legsRoot + ",", "m_CorrespondingSourceObject: {fileID: " + avatar + ","));

                // A mannequin part back on the built-in Default-Material, the Ground material on the built-in Standard shader,
                // and the Pit material on a URP-only shader (all magenta in one pipeline or the other).
                Edit(legs, t => ReplaceFirst(t, PrimitiveMaterials.Mannequin.Ref, "{fileID: 10303, guid: 0000000000000000f000000000000000, type: 0}"));
                string shaderRef = UnityYaml.Ref(PrimitiveMaterials.ShaderFileId, PrimitiveMaterials.ShaderGuid, 3);
                Edit(Path.Combine(copy, PrimitiveMaterials.Ground.Path), t => t.Replace(shaderRef, "{fileID: 46, guid: 0000000000000000f000000000000000, type: 0}"));
                string urpOnly = Path.Combine(copy, PrimitiveMaterials.Folder, "UrpOnly.shader");
                File.WriteAllText(urpOnly, UrpOnlyShader);
                File.WriteAllText(urpOnly + ".meta", UnityMeta.Text(urpOnly, "fedcbafedcbafedcbafedcbafedcbafe"));
                Edit(Path.Combine(copy, PrimitiveMaterials.Pit.Path), t => t.Replace(shaderRef, UnityYaml.Ref(PrimitiveMaterials.ShaderFileId, "fedcbafedcbafedcbafedcbafedcbafe", 3)));

                var problems = string.Join("\n", UnityAssetCheck.Problems(copy));
                Assert.That(problems, Does.Contain("HeadGait Legs.prefab: &").And.Contain("built-in material 10303 (Default-Material, Standard shader) renders magenta in URP"));
                Assert.That(problems, Does.Contain("HeadGait Ground.mat uses built-in shader 46 (Standard), magenta in URP"));
                Assert.That(problems, Does.Contain("HeadGait Pit.mat's shader UrpOnly.shader has no SubShader and Pass the built-in pipeline draws"));
                Assert.That(problems, Does.Not.Contain("HeadGait Pit.mat's shader UrpOnly.shader has no SubShader and Pass the URP pipeline draws"));
                Assert.That(problems, Does.Contain("HeadGait Pit.mat's shader UrpOnly.shader is not drawn in URP's depth prepass"));
                Assert.That(problems, Does.Not.Contain("HeadGait Primitive.shader is not drawn in URP's depth prepass"));
                Assert.That(problems, Does.Contain($"transform &{instanceRoot} (a prefab instance's root) is not listed in its father"));
                Assert.That(problems, Does.Contain("field 'positionLag' is not declared in FollowHead.cs"));
                Assert.That(problems, Does.Contain($"stripped transform &{instanceRoot} of prefab instance").And.Contain("is not the root Transform of its source prefab"));
                Assert.That(problems, Does.Contain("parameter StridePhase (AnimatorParameters) is missing"));
                Assert.That(problems, Does.Contain("parameter Stride is not in AnimatorParameters"));
                Assert.That(problems, Does.Contain("does not take its normalized time from StridePhase"));
                Assert.That(problems, Does.Contain($"local fileID {walkingState} resolves to nothing"));
                Assert.That(problems, Does.Contain("transition StartWalkLeft->Walking is missing"));
                Assert.That(problems, Does.Contain("field 'animator' is not declared in HeadImuSource.cs"));
                Assert.That(problems, Does.Contain("not a .cs file declaring class Misnamed"));
                Assert.That(problems, Does.Contain("guid 0123456789abcdef0123456789abcdef resolves to no .meta"));
                Assert.That(problems, Does.Contain("local fileID 42 resolves to nothing"));
                Assert.That(problems, Does.Contain("Walking.anim: no key at the Right initial contact").Or.Contain("Walking.anim: the Right foot does not land"));
                Assert.That(problems, Does.Contain("Humanoid/Start Walk Right.anim: no key at the Right initial contact").Or.Contain("Humanoid/Start Walk Right.anim: the Right foot does not land"));
                Assert.That(problems, Does.Contain("clip 'Standing' is overridden by 'Idle'"));
            }
            finally
            {
                Directory.Delete(copy, true);
            }
        }

        const string UrpOnlyShader = "Shader \"Test/URP Lit\"\n{\n    SubShader\n    {\n        Tags { \"RenderPipeline\" = \"UniversalPipeline\" }\n" +
                                     "        Pass\n        {\n            Tags { \"LightMode\" = \"UniversalForward\" }\n            HLSLPROGRAM\n            float4 f() { return 0; }\n            ENDHLSL\n        }\n    }\n}\n";

        [Test]
        public void ThePrimitiveShaderIsDrawnByBothPipelinesAndOthersOnlyByTheirOwn()
        {
            Assert.That(ShaderPasses.Draws(PrimitiveMaterials.ShaderSource, ShaderPasses.BuiltIn), Is.True);
            Assert.That(ShaderPasses.Draws(PrimitiveMaterials.ShaderSource, ShaderPasses.Universal), Is.True);
            Assert.That(ShaderPasses.Draws(UrpOnlyShader, ShaderPasses.Universal), Is.True);
            Assert.That(ShaderPasses.Draws(UrpOnlyShader, ShaderPasses.BuiltIn), Is.False);
            // A surface shader (like Standard): built-in generates ForwardBase passes from it; URP draws none of them.
            const string surface = "Shader \"Test/Surface\" { SubShader { Tags { \"RenderType\" = \"Opaque\" }\n CGPROGRAM\n #pragma surface surf Lambert\n struct Input { float2 uv; };\n void surf(Input i, inout SurfaceOutput o) { o.Albedo = 1; }\n ENDCG\n } }";
            Assert.That(ShaderPasses.Draws(surface, ShaderPasses.BuiltIn), Is.True);
            Assert.That(ShaderPasses.Draws(surface, ShaderPasses.Universal), Is.False);
            // A pass only for the shadow map draws nothing visible in either.
            const string shadowOnly = "Shader \"Test/Shadow\" { SubShader { Pass { Tags { \"LightMode\" = \"ShadowCaster\" } } } }";
            Assert.That(ShaderPasses.Draws(shadowOnly, ShaderPasses.BuiltIn), Is.False);
            Assert.That(ShaderPasses.Draws(shadowOnly, ShaderPasses.Universal), Is.False);
        }

        /// <summary>
        /// The primitives cast shadows in both pipelines (a ShadowCaster pass; `Fallback Off` supplies none) and URP draws
        /// them in its depth prepass, DepthOnly and DepthNormals: under depth priming URP draws the opaques with ZTest Equal
        /// against that prepass, so a shader it does not draw there is invisible (URP's DrawObjectsPass, UniversalRenderer).
        /// </summary>
        [Test]
        public void ThePrimitiveShaderCastsShadowsAndIsDrawnInUrpsDepthPrepass()
        {
            string shader = PrimitiveMaterials.ShaderSource;
            Assert.That(ShaderPasses.Fallback(shader), Is.Null, "Fallback Off");
            Assert.That(ShaderPasses.CastsShadows(shader, ShaderPasses.BuiltIn), Is.True, "built-in shadow caster");
            Assert.That(ShaderPasses.CastsShadows(shader, ShaderPasses.Universal), Is.True, "URP shadow caster");
            Assert.That(ShaderPasses.InUrpDepthPrepass(shader, normals: false), Is.True, "DepthOnly");
            Assert.That(ShaderPasses.InUrpDepthPrepass(shader, normals: true), Is.True, "DepthNormals");
            Assert.That(ShaderPasses.VisibleUnderUrpDepthPriming(shader), Is.True);
        }

        /// <summary>
        /// The primitives' shadow caster applies URP's bias under URP (its depth and normal bias from _ShadowBias along
        /// _LightDirection, or toward _LightPosition for spot and point lights, and the near-plane clamp, as URP's
        /// ShadowCasterPass.hlsl does) and keeps UnityCG's macros, the built-in pipeline's bias, for the built-in pipeline.
        /// </summary>
        [Test]
        public void ThePrimitiveShadowCasterAppliesEachPipelinesBias()
        {
            string shader = PrimitiveMaterials.ShaderSource;
            Assert.That(ShaderPasses.MissingUrpShadowBias(shader), Is.Empty, "URP's shadow bias");
            foreach (var pipeline in new[] { ShaderPasses.BuiltIn, ShaderPasses.Universal })
            {
                string caster = ShaderPasses.PassPrograms(shader, "ShadowCaster", pipeline).Single();
                Assert.That(caster, Does.Contain("#pragma multi_compile_shadowcaster").And.Contain("TRANSFER_SHADOW_CASTER_NORMALOFFSET(o)")
                    .And.Contain("SHADOW_CASTER_FRAGMENT(i)"), pipeline + ": UnityCG's shadow caster (the built-in bias)");
                Assert.That(caster, Does.Not.Contain("com.unity.render-pipelines"), pipeline + ": no URP include");
            }
            // URP's spot and point light slices set _ShadowBias and _LightPosition but not _LightDirection
            // (AdditionalLightsShadowCasterPass), which stays zero where no main light shadow was drawn: under their keyword,
            // which only URP turns on, URP's bias applies whatever _LightDirection holds.
            string urpCaster = ShaderPasses.PassPrograms(shader, "ShadowCaster", ShaderPasses.Universal).Single();
            Assert.That(urpCaster, Does.Match(@"bool UrpShadowPass\(\)\s*\{\s*#if defined\(_CASTING_PUNCTUAL_LIGHT_SHADOW\)\s*return true;"));
        }

        [Test]
        public void TheCommittedPrimitiveShaderIsTheGeneratedOne()
        {
            string committed = File.ReadAllText(Path.Combine(Package, PrimitiveMaterials.ShaderPath)).Replace("\r\n", "\n");
            Assert.That(committed, Is.EqualTo(PrimitiveMaterials.ShaderSource.Replace("\r\n", "\n")), "regenerate with `dotnet run --project dotnet/HeadGait.Cli -c Release -- clips`");
        }

        /// <summary>The pass model on small shaders, so that it cannot pass the primitive shader trivially.</summary>
        [Test]
        public void ShadowCastersAndTheUrpDepthPrepassAreReadFromTheLightModes()
        {
            // URP-only, colour pass only: drawn, but in no prepass and no shadow map.
            Assert.That(ShaderPasses.Draws(UrpOnlyShader, ShaderPasses.Universal), Is.True);
            Assert.That(ShaderPasses.InUrpDepthPrepass(UrpOnlyShader, false), Is.False);
            Assert.That(ShaderPasses.InUrpDepthPrepass(UrpOnlyShader, true), Is.False);
            Assert.That(ShaderPasses.VisibleUnderUrpDepthPriming(UrpOnlyShader), Is.False);
            Assert.That(ShaderPasses.CastsShadows(UrpOnlyShader, ShaderPasses.Universal), Is.False);
            Assert.That(ShaderPasses.CastsShadows(UrpOnlyShader, ShaderPasses.BuiltIn), Is.False);

            // URP-only with DepthOnly (a comment naming DepthNormals does not count): the depth prepass draws it, the normals one not.
            string urpDepth = UrpOnlyShader.Replace("    }\n}\n",
                "        // no \"LightMode\" = \"DepthNormals\" pass\n        Pass { Name \"DepthOnly\" Tags { \"LightMode\" = \"DepthOnly\" } ZWrite On ColorMask R }\n    }\n}\n");
            Assert.That(urpDepth, Is.Not.EqualTo(UrpOnlyShader));
            Assert.That(ShaderPasses.InUrpDepthPrepass(urpDepth, false), Is.True);
            Assert.That(ShaderPasses.InUrpDepthPrepass(urpDepth, true), Is.False);
            Assert.That(ShaderPasses.VisibleUnderUrpDepthPriming(urpDepth), Is.False);
            string urpDepthNormals = urpDepth.Replace("    }\n}\n", "        Pass { Tags { \"LightMode\" = \"DepthNormalsOnly\" } }\n    }\n}\n");
            Assert.That(ShaderPasses.InUrpDepthPrepass(urpDepthNormals, true), Is.True);
            Assert.That(ShaderPasses.VisibleUnderUrpDepthPriming(urpDepthNormals), Is.True);
            Assert.That(ShaderPasses.Draws(urpDepthNormals, ShaderPasses.BuiltIn), Is.False);

            // Shadow-only: in both shadow maps, drawn nowhere, so not visible under priming either.
            const string shadowOnly = "Shader \"Test/Shadow\" { SubShader { Pass { Tags { \"LightMode\" = \"ShadowCaster\" } } } }";
            Assert.That(ShaderPasses.CastsShadows(shadowOnly, ShaderPasses.BuiltIn), Is.True);
            Assert.That(ShaderPasses.CastsShadows(shadowOnly, ShaderPasses.Universal), Is.True);
            Assert.That(ShaderPasses.VisibleUnderUrpDepthPriming(shadowOnly), Is.False);

            // A ShadowCaster pass in a URP-tagged SubShader is URP's alone.
            const string urpShadow = "Shader \"Test/UrpShadow\" { SubShader { Tags { \"RenderPipeline\" = \"UniversalPipeline\" } Pass { Tags { \"LightMode\" = \"ShadowCaster\" } } } }";
            Assert.That(ShaderPasses.CastsShadows(urpShadow, ShaderPasses.Universal), Is.True);
            Assert.That(ShaderPasses.CastsShadows(urpShadow, ShaderPasses.BuiltIn), Is.False);

            // Built-in finds a shadow caster in a Fallback; Fallback Off gives none; UsePass pulls one in for both.
            const string unlit = "Shader \"Test/Unlit\" { SubShader { Pass { CGPROGRAM\n float4 f() { return 0; }\n ENDCG } } FALLBACK_CLAUSE }";
            string withFallback = unlit.Replace("FALLBACK_CLAUSE", "Fallback \"Legacy Shaders/VertexLit\"");
            Assert.That(ShaderPasses.Fallback(withFallback), Is.EqualTo("Legacy Shaders/VertexLit"));
            Assert.That(ShaderPasses.CastsShadows(withFallback, ShaderPasses.BuiltIn), Is.True);
            Assert.That(ShaderPasses.CastsShadows(withFallback, ShaderPasses.Universal), Is.False);
            string fallbackOff = unlit.Replace("FALLBACK_CLAUSE", "Fallback Off");
            Assert.That(ShaderPasses.Fallback(fallbackOff), Is.Null);
            Assert.That(ShaderPasses.CastsShadows(fallbackOff, ShaderPasses.BuiltIn), Is.False);
            Assert.That(ShaderPasses.CastsShadows(unlit.Replace("FALLBACK_CLAUSE", ""), ShaderPasses.BuiltIn), Is.False);
            string usePass = unlit.Replace("} } FALLBACK_CLAUSE", "} UsePass \"Legacy Shaders/VertexLit/SHADOWCASTER\" } Fallback Off");
            Assert.That(ShaderPasses.CastsShadows(usePass, ShaderPasses.BuiltIn), Is.True);
            Assert.That(ShaderPasses.CastsShadows(usePass, ShaderPasses.Universal), Is.True);
            // The unlit pass has no LightMode: URP's colour pass draws it, its prepass does not.
            Assert.That(ShaderPasses.Draws(fallbackOff, ShaderPasses.Universal), Is.True);
            Assert.That(ShaderPasses.VisibleUnderUrpDepthPriming(fallbackOff), Is.False);
        }

        /// <summary>The URP shadow-bias model on small shaders, so that it cannot pass the primitive shader trivially.</summary>
        [Test]
        public void UrpsShadowBiasIsReadFromTheShadowCasterPassProgram()
        {
            // UnityCG's macros alone (the built-in pipeline's bias): every URP term is missing.
            string unityCg = ShadowCasterShader("#pragma multi_compile_shadowcaster\n#include \"UnityCG.cginc\"\n" +
                "struct v2f { V2F_SHADOW_CASTER; };\nv2f vert(appdata_base v) { v2f o; TRANSFER_SHADOW_CASTER_NORMALOFFSET(o) return o; }\n" +
                "// URP's _ShadowBias.x, _ShadowBias.y and _LightDirection are not applied (a comment does not count)\n" +
                "float4 frag(v2f i) : SV_Target { SHADOW_CASTER_FRAGMENT(i) }\n");
            var missing = ShaderPasses.MissingUrpShadowBias(unityCg);
            Assert.That(missing, Has.Some.Contains("_ShadowBias.x").And.Some.Contains("_ShadowBias.y").And.Some.Contains("_LightDirection")
                .And.Some.Contains("_CASTING_PUNCTUAL_LIGHT_SHADOW keyword").And.Some.Contains("near plane"));

            // All of URP's terms: nothing missing; each one dropped is named.
            string urp = ShadowCasterShader(UrpBiasProgram);
            Assert.That(ShaderPasses.MissingUrpShadowBias(urp), Is.Empty);
            Assert.That(ShaderPasses.MissingUrpShadowBias(urp.Replace("min(p.z, UNITY_NEAR_CLIP_VALUE)", "p.z")), Is.EqualTo(new[]
                { "clip-space z is not clamped to the near plane (UNITY_NEAR_CLIP_VALUE, min under UNITY_REVERSED_Z, max otherwise)" }));
            Assert.That(ShaderPasses.MissingUrpShadowBias(urp.Replace("_ShadowBias.y", "0")), Is.EqualTo(new[] { "_ShadowBias.y (URP's normal bias) is not read" }));
            Assert.That(ShaderPasses.MissingUrpShadowBias(urp.Replace("#pragma multi_compile_vertex _ _CASTING_PUNCTUAL_LIGHT_SHADOW\n", "")),
                Is.EqualTo(new[] { "no _CASTING_PUNCTUAL_LIGHT_SHADOW keyword" }));
            Assert.That(ShaderPasses.MissingUrpShadowBias(urp.Replace("normalize(_LightPosition - w)", "_LightDirection")),
                Is.EqualTo(new[] { "_LightPosition is not read under _CASTING_PUNCTUAL_LIGHT_SHADOW" }));
            // Commented out, the terms are gone.
            Assert.That(ShaderPasses.MissingUrpShadowBias(urp.Replace("w += l * _ShadowBias.x", "// w += l * _ShadowBias.x")), Has.Some.Contains("_ShadowBias.x"));

            // URP's own ShadowCasterPass.hlsl has them all; a URP-tagged SubShader counts for URP.
            string urpInclude = ShadowCasterShader("#include \"Packages/com.unity.render-pipelines.universal/Shaders/ShadowCasterPass.hlsl\"\n")
                .Replace("SubShader {", "SubShader { Tags { \"RenderPipeline\" = \"UniversalPipeline\" }");
            Assert.That(ShaderPasses.MissingUrpShadowBias(urpInclude), Is.Empty);

            // The terms in a SubShader only the built-in pipeline uses, or in another pass, do not count; nor does no caster.
            Assert.That(ShaderPasses.MissingUrpShadowBias(urp.Replace("SubShader {", "SubShader { Tags { \"RenderPipeline\" = \"HDRenderPipeline\" }")),
                Is.EqualTo(new[] { "no ShadowCaster pass URP draws" }));
            Assert.That(ShaderPasses.MissingUrpShadowBias(urp.Replace("\"ShadowCaster\"", "\"DepthOnly\"")), Is.EqualTo(new[] { "no ShadowCaster pass URP draws" }));
            Assert.That(ShaderPasses.MissingUrpShadowBias(UrpOnlyShader), Is.EqualTo(new[] { "no ShadowCaster pass URP draws" }));
            // The SubShader's CGINCLUDE is part of every pass's program.
            string shared = "Shader \"Test/Shared\" { SubShader {\nCGINCLUDE\n" + UrpBiasProgram + "ENDCG\n" +
                            "Pass { Tags { \"LightMode\" = \"ShadowCaster\" }\nCGPROGRAM\n#pragma vertex vert\nENDCG\n} } }";
            Assert.That(ShaderPasses.MissingUrpShadowBias(shared), Is.Empty);
            Assert.That(ShaderPasses.PassPrograms(shared, "ShadowCaster", ShaderPasses.BuiltIn).Single(), Does.Contain("_ShadowBias.x").And.Contain("#pragma vertex vert"));
        }

        static string ShadowCasterShader(string program) =>
            "Shader \"Test/Caster\" { SubShader {\n Pass { Tags { \"LightMode\" = \"ShadowCaster\" }\nCGPROGRAM\n" + program + "ENDCG\n}\n} Fallback Off }";

        const string UrpBiasProgram =
            "#pragma multi_compile_vertex _ _CASTING_PUNCTUAL_LIGHT_SHADOW\nfloat4 _ShadowBias; float3 _LightDirection; float3 _LightPosition;\n" +
            "float4 vert(float4 v : POSITION, float3 n : NORMAL) : SV_POSITION {\n float3 w = mul(unity_ObjectToWorld, v).xyz;\n" +
            "#if defined(_CASTING_PUNCTUAL_LIGHT_SHADOW)\n float3 l = normalize(_LightPosition - w);\n#else\n float3 l = _LightDirection;\n#endif\n" +
            " w += l * _ShadowBias.x + n * (1 - saturate(dot(l, n))) * _ShadowBias.y;\n float4 p = mul(UNITY_MATRIX_VP, float4(w, 1));\n" +
            "#if defined(UNITY_REVERSED_Z)\n p.z = min(p.z, UNITY_NEAR_CLIP_VALUE);\n#else\n p.z = max(p.z, UNITY_NEAR_CLIP_VALUE);\n#endif\n return p;\n}\n";

        [Test]
        public void StrippedDocumentsAndTagsAreSplitBeforeParsing()
        {
            const string text = "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!1001 &5\nPrefabInstance:\n  m_SourcePrefab: {fileID: 100100000, guid: abc, type: 3}\n" +
                                "--- !u!114 &-7 stripped\nMonoBehaviour:\n  m_PrefabInstance: {fileID: 5}\n";
            var docs = UnityYamlFile.Parse(text, "test.unity");
            Assert.That(docs.Select(d => (d.ClassId, d.FileId, d.Stripped, d.Type)), Is.EqualTo(new[] { (1001, 5L, false, "PrefabInstance"), (114, -7L, true, "MonoBehaviour") }));
            Assert.That(() => UnityYamlFile.Parse("--- !u!1 &1\nGameObject:\n  m_Name: [unclosed\n", "bad.prefab"), Throws.TypeOf<FormatException>().With.Message.Contains("bad.prefab"));
        }

        static void Edit(string path, Func<string, string> change)
        {
            string before = File.ReadAllText(path);
            string after = change(before);
            Assert.That(after, Is.Not.EqualTo(before), "the edit to " + Path.GetFileName(path) + " changed nothing");
            File.WriteAllText(path, after);
        }

        static string ReplaceFirst(string text, string what, string with)
        {
            int i = text.IndexOf(what, StringComparison.Ordinal);
            return i < 0 ? text : text.Substring(0, i) + with + text.Substring(i + what.Length);
        }

        /// <summary>The parts of the package the assets refer to (scripts, template, recordings, assets), in a temp folder.</summary>
        static string CopyOfPackage()
        {
            string copy = Path.Combine(Path.GetTempPath(), "headgait-assets-" + Guid.NewGuid().ToString("N"));
            foreach (var folder in new[] { "Runtime/Animation", "Runtime/Animation/Humanoid", "Runtime/Materials", "Runtime/Prefabs", "Runtime/Components", "Runtime/Components/Study", "Samples~/Legs", "Samples~/Study", "Samples~/Recordings/eval" })
            {
                foreach (var file in Directory.GetFiles(Path.Combine(Package, folder)))
                {
                    string target = Path.Combine(copy, folder, Path.GetFileName(file));
                    Directory.CreateDirectory(Path.GetDirectoryName(target));
                    File.Copy(file, target);
                }
            }
            Directory.CreateDirectory(Path.Combine(copy, "Models"));
            foreach (var f in new[] { GaitAssetFiles.CorTemplate, GaitAssetFiles.CorTemplate + ".meta" })
                File.Copy(Path.Combine(Package, f), Path.Combine(copy, f));
            return copy;
        }
    }
}
