using System;
using System.Collections.Generic;
using HeadGait.Study;
using UnityEngine;

namespace HeadGait.Unity
{
    /// <summary>One VR condition and the scene object that shows it (none for the no-avatar condition).</summary>
    [Serializable]
    public sealed class AvatarCondition
    {
        [Tooltip("Condition name as in the study settings, e.g. no-avatar, block-avatar, humanoid-avatar.")]
        public string condition;
        [Tooltip("Shown while this condition is walked; may be empty (no avatar).")]
        public GameObject root;
    }

    /// <summary>
    /// Shows the avatar of one study condition at a time (the no-avatar, block-avatar and humanoid-avatar roots of the
    /// study scene) and hides the others; null shows none.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("HeadGait/Study/Avatar Condition Switcher")]
    public sealed class AvatarConditionSwitcher : MonoBehaviour
    {
        [SerializeField] List<AvatarCondition> avatars = new List<AvatarCondition>
        {
            new AvatarCondition { condition = StudyConfig.NoAvatar },
            new AvatarCondition { condition = StudyConfig.BlockAvatar },
            new AvatarCondition { condition = StudyConfig.HumanoidAvatar },
        };

        bool applied;

        /// <summary>The condition shown, or null for none.</summary>
        public string Shown { get; private set; }

        public IReadOnlyList<AvatarCondition> Avatars => avatars;

        /// <summary>Lets code (and tests) set the conditions the inspector normally holds.</summary>
        public void Configure(IEnumerable<AvatarCondition> conditions)
        {
            avatars = new List<AvatarCondition>(conditions);
            applied = false;
        }

        /// <summary>Shows the condition's avatar and hides every other; false when the condition has no entry (nothing is shown then).</summary>
        public bool Show(string condition)
        {
            bool known = condition == null || Find(condition) != null;
            string target = known ? condition : null;
            if (applied && target == Shown) return known;
            foreach (var a in avatars)
                if (a.root != null) a.root.SetActive(target != null && a.condition == target);
            Shown = target;
            applied = true;
            return known;
        }

        /// <summary>The study conditions that have no entry here (a setup error the operator view reports).</summary>
        public List<string> Missing(IEnumerable<string> conditions)
        {
            var missing = new List<string>();
            foreach (var c in conditions)
                if (Find(c) == null) missing.Add(c);
            return missing;
        }

        AvatarCondition Find(string condition)
        {
            foreach (var a in avatars)
                if (a != null && a.condition == condition) return a;
            return null;
        }
    }
}
