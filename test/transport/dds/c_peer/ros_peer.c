// Copyright 2026 The tf_demo Authors
//
// Licensed under the Apache License, Version 2.0 (the "License");
// you may not use this file except in compliance with the License.
// You may obtain a copy of the License at
//
//     http://www.apache.org/licenses/LICENSE-2.0
//
// Unless required by applicable law or agreed to in writing, software
// distributed under the License is distributed on an "AS IS" BASIS,
// WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
// See the License for the specific language governing permissions and
// limitations under the License.

// A foreign ROS-like peer for interop tests: plain Cyclone DDS 0.10 C, endpoints configured as
// rmw_cyclonedds configures them (types compiled with `idlc -t`, i.e. no type information;
// DataRepresentation XCDR1 only; the same QoS, topic and type names; typehash USER_DATA) and
// discovery configured with rmw_cyclonedds' LOCALHOST fragment.
//
// Usage (domain from ROS_DOMAIN_ID):
//   ros_peer pub-tf COUNT TIMEOUT_S        wait for a reader on rt/tf, write COUNT TFMessages
//   ros_peer sub-tf COUNT TIMEOUT_S        print the transforms of COUNT TFMessages from rt/tf
//   ros_peer pub-static HOLD_S             latch one TFMessage (2 transforms) on rt/tf_static
//   ros_peer sub-static COUNT TIMEOUT_S    late joiner: print COUNT transforms from rt/tf_static
//   ros_peer discovery NAME TIMEOUT_S      read ros_discovery_info until node NAME appears
// Every received transform is printed as "tf <parent> <child> <x> <y> <z> <qx> <qy> <qz> <qw>";
// exit status 0 on success, 1 on timeout, 2 on a DDS error.

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dds/dds.h"
#include "ros_types.h"

#define TF_TYPEHASH "typehash=RIHS01_e369d0f05a23ae52508854b66f6aa0437f3449d652e8cbf22d5abe85d020f087;"
#define PEI_TYPEHASH "typehash=RIHS01_91a0593bacdcc50ea9bdcf849a938b128412cc1ea821245c663bcd26f83c295e;"

static const char *LOCALHOST_CONFIG =
  "<CycloneDDS><Domain id=\"any\"><General><AllowMulticast>false</AllowMulticast></General>"
  "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
  "<MaxAutoParticipantIndex>32</MaxAutoParticipantIndex>"
  "<Peers><Peer address=\"localhost\"/></Peers></Discovery></Domain></CycloneDDS>";

static void check (dds_return_t rc, const char *what)
{
  if (rc < 0)
  {
    fprintf (stderr, "ros_peer: %s: %s\n", what, dds_strretcode (rc));
    exit (2);
  }
}

// The QoS rmw_cyclonedds' create_readwrite_qos() builds.
static dds_qos_t *rmw_qos (bool transient_local, bool keep_all, int32_t depth, const char *typehash)
{
  dds_qos_t *qos = dds_create_qos ();
  dds_qset_reliability (qos, DDS_RELIABILITY_RELIABLE, DDS_INFINITY);
  if (keep_all)
    dds_qset_history (qos, DDS_HISTORY_KEEP_ALL, DDS_LENGTH_UNLIMITED);
  else
    dds_qset_history (qos, DDS_HISTORY_KEEP_LAST, depth);
  if (transient_local)
  {
    dds_qset_durability (qos, DDS_DURABILITY_TRANSIENT_LOCAL);
    dds_qset_durability_service (
      qos, 0, keep_all ? DDS_HISTORY_KEEP_ALL : DDS_HISTORY_KEEP_LAST, depth,
      DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED);
  }
  else
    dds_qset_durability (qos, DDS_DURABILITY_VOLATILE);
  dds_qset_writer_data_lifecycle (qos, false);
  dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
  dds_qset_data_representation (qos, 1, &xcdr1);
  dds_qset_userdata (qos, typehash, strlen (typehash));
  return qos;
}

static dds_entity_t make_participant (void)
{
  const char *domain_text = getenv ("ROS_DOMAIN_ID");
  dds_domainid_t domain = domain_text ? (dds_domainid_t) strtoul (domain_text, NULL, 0) : 0;
  check (dds_create_domain (domain, LOCALHOST_CONFIG), "dds_create_domain");
  dds_qos_t *qos = dds_create_qos ();
  dds_qset_userdata (qos, "enclave=/;", strlen ("enclave=/;"));
  dds_entity_t participant = dds_create_participant (domain, qos, NULL);
  dds_delete_qos (qos);
  check (participant, "dds_create_participant");
  return participant;
}

static dds_entity_t make_endpoint (
  dds_entity_t participant, const char *topic_name, const dds_topic_descriptor_t *desc,
  bool writer, bool transient_local, bool keep_all, int32_t depth, const char *typehash)
{
  dds_entity_t topic = dds_create_topic (participant, desc, topic_name, NULL, NULL);
  check (topic, "dds_create_topic");
  dds_qos_t *qos = rmw_qos (transient_local, keep_all, depth, typehash);
  dds_entity_t entity = writer ? dds_create_writer (participant, topic, qos, NULL)
                               : dds_create_reader (participant, topic, qos, NULL);
  dds_delete_qos (qos);
  check (entity, writer ? "dds_create_writer" : "dds_create_reader");
  return entity;
}

static void fill_transform (
  geometry_msgs_msg_dds__TransformStamped_ *t, const char *parent, const char *child, double x)
{
  t->header.stamp.sec = 1;
  t->header.stamp.nanosec = 2;
  t->header.frame_id = (char *) parent;
  t->child_frame_id = (char *) child;
  t->transform.translation.x = x;
  t->transform.translation.y = 0.25;
  t->transform.translation.z = -1.5;
  t->transform.rotation.x = 0.0;
  t->transform.rotation.y = 0.0;
  t->transform.rotation.z = 0.6;
  t->transform.rotation.w = 0.8;
}

static void print_message (const tf2_msgs_msg_dds__TFMessage_ *msg)
{
  for (uint32_t i = 0; i < msg->transforms._length; i++)
  {
    const geometry_msgs_msg_dds__TransformStamped_ *t = &msg->transforms._buffer[i];
    printf (
      "tf %s %s %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", t->header.frame_id,
      t->child_frame_id, t->transform.translation.x, t->transform.translation.y,
      t->transform.translation.z, t->transform.rotation.x, t->transform.rotation.y,
      t->transform.rotation.z, t->transform.rotation.w);
  }
  fflush (stdout);
}

// Take what `reader` holds and hand each valid sample to `on_sample`; return how many were taken.
typedef void (*sample_fn) (const void *sample, void *context);

static int take_each (dds_entity_t reader, sample_fn on_sample, void *context)
{
  void *samples[16] = {NULL};
  dds_sample_info_t infos[16];
  dds_return_t n = dds_take (reader, samples, infos, 16, 16);
  check (n, "dds_take");
  for (int i = 0; i < n; i++)
    if (infos[i].valid_data)
      on_sample (samples[i], context);
  if (n > 0)
    dds_return_loan (reader, samples, n);
  return n;
}

static bool wait_for_match (dds_entity_t writer, dds_time_t deadline)
{
  while (dds_time () < deadline)
  {
    dds_publication_matched_status_t status;
    check (dds_get_publication_matched_status (writer, &status), "matched status");
    if (status.current_count > 0)
      return true;
    dds_sleepfor (DDS_MSECS (10));
  }
  return false;
}

static int publish_tf (int count, double timeout_s)
{
  dds_entity_t participant = make_participant ();
  dds_entity_t writer = make_endpoint (
    participant, "rt/tf", &tf2_msgs_msg_dds__TFMessage__desc, true, false, false, 100, TF_TYPEHASH);
  if (!wait_for_match (writer, dds_time () + (dds_duration_t) (timeout_s * 1e9)))
  {
    fprintf (stderr, "ros_peer: no reader on rt/tf\n");
    return 1;
  }
  for (int i = 0; i < count; i++)
  {
    geometry_msgs_msg_dds__TransformStamped_ transform;
    fill_transform (&transform, "c_parent", "c_child", (double) i);
    tf2_msgs_msg_dds__TFMessage_ msg = {
      .transforms = {._length = 1, ._maximum = 1, ._buffer = &transform, ._release = false}};
    check (dds_write (writer, &msg), "dds_write");
    dds_sleepfor (DDS_MSECS (2));
  }
  check (dds_wait_for_acks (writer, DDS_SECS (5)), "dds_wait_for_acks");
  printf ("published %d\n", count);
  fflush (stdout);
  dds_delete (participant);
  return 0;
}

struct tf_count
{
  bool transient_local;  // count transforms (a latched message holds several), else messages
  int received;
};

static void count_tf (const void *sample, void *context)
{
  const tf2_msgs_msg_dds__TFMessage_ *msg = sample;
  struct tf_count *count = context;
  print_message (msg);
  count->received += (int) (count->transient_local ? msg->transforms._length : 1);
}

static int read_tf (const char *topic_name, bool transient_local, int count, double timeout_s)
{
  dds_entity_t participant = make_participant ();
  dds_entity_t reader = make_endpoint (
    participant, topic_name, &tf2_msgs_msg_dds__TFMessage__desc, false, transient_local, false,
    100, TF_TYPEHASH);
  dds_entity_t waitset = dds_create_waitset (participant);
  dds_entity_t condition = dds_create_readcondition (reader, DDS_ANY_STATE);
  check (dds_waitset_attach (waitset, condition, 0), "dds_waitset_attach");
  dds_time_t deadline = dds_time () + (dds_duration_t) (timeout_s * 1e9);
  struct tf_count received = {transient_local, 0};
  while (received.received < count && dds_time () < deadline)
  {
    dds_waitset_wait_until (waitset, NULL, 0, deadline);
    take_each (reader, count_tf, &received);
  }
  dds_delete (participant);
  return received.received >= count ? 0 : 1;
}

static int publish_static (double hold_s)
{
  dds_entity_t participant = make_participant ();
  dds_entity_t writer = make_endpoint (
    participant, "rt/tf_static", &tf2_msgs_msg_dds__TFMessage__desc, true, true, false, 1,
    TF_TYPEHASH);
  geometry_msgs_msg_dds__TransformStamped_ transforms[2];
  fill_transform (&transforms[0], "c_base", "c_static_a", 1.0);
  fill_transform (&transforms[1], "c_base", "c_static_b", 2.0);
  tf2_msgs_msg_dds__TFMessage_ msg = {
    .transforms = {._length = 2, ._maximum = 2, ._buffer = transforms, ._release = false}};
  check (dds_write (writer, &msg), "dds_write");
  printf ("latched\n");
  fflush (stdout);
  dds_sleepfor ((dds_duration_t) (hold_s * 1e9));
  dds_delete (participant);
  return 0;
}

struct node_search
{
  const char *name;
  bool found;
};

static void find_node (const void *sample, void *context)
{
  const rmw_dds_common_msg_dds__ParticipantEntitiesInfo_ *info = sample;
  struct node_search *search = context;
  for (uint32_t k = 0; k < info->node_entities_info_seq._length; k++)
  {
    const rmw_dds_common_msg_dds__NodeEntitiesInfo_ *node =
      &info->node_entities_info_seq._buffer[k];
    printf (
      "node %s %s readers=%u writers=%u\n", node->node_namespace, node->node_name,
      node->reader_gid_seq._length, node->writer_gid_seq._length);
    if (strcmp (node->node_name, search->name) == 0)
      search->found = true;
  }
}

static int discovery (const char *node_name, double timeout_s)
{
  dds_entity_t participant = make_participant ();
  dds_entity_t reader = make_endpoint (
    participant, "ros_discovery_info",
    &rmw_dds_common_msg_dds__ParticipantEntitiesInfo__desc, false, true, true, 1, PEI_TYPEHASH);
  dds_time_t deadline = dds_time () + (dds_duration_t) (timeout_s * 1e9);
  struct node_search search = {node_name, false};
  while (!search.found && dds_time () < deadline)
    if (take_each (reader, find_node, &search) == 0)
      dds_sleepfor (DDS_MSECS (20));
  fflush (stdout);
  dds_delete (participant);
  return search.found ? 0 : 1;
}

int main (int argc, char **argv)
{
  if (argc >= 4 && strcmp (argv[1], "pub-tf") == 0)
    return publish_tf (atoi (argv[2]), atof (argv[3]));
  if (argc >= 4 && strcmp (argv[1], "sub-tf") == 0)
    return read_tf ("rt/tf", false, atoi (argv[2]), atof (argv[3]));
  if (argc >= 3 && strcmp (argv[1], "pub-static") == 0)
    return publish_static (atof (argv[2]));
  if (argc >= 4 && strcmp (argv[1], "sub-static") == 0)
    return read_tf ("rt/tf_static", true, atoi (argv[2]), atof (argv[3]));
  if (argc >= 4 && strcmp (argv[1], "discovery") == 0)
    return discovery (argv[2], atof (argv[3]));
  fprintf (stderr, "usage: ros_peer pub-tf|sub-tf|pub-static|sub-static|discovery ...\n");
  return 2;
}
