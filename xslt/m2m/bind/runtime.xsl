<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/runtime.xsl - bind (xslt/m2m/bind.xsl): the runtime and
  computational architecture of seed 002: processes, threads, component
  sets, and the buses between hosts.

  Reads:   the PIM (urn:robomda:pim:1) and the instances of fp:binding.
  Writes:  parts of pim:binding (schemas/pim/1/binding.xsd), or values.
  Params:  none.  Keys: those of bind.xsl, and fp:component-set (below).
  Provides: fp:is-thread, fp:process-of, fp:is-set, fp:set-deployment,
           fp:sets-of, fp:processes, fp:component-sets, fp:links,
           fp:thread-activity, fp:member-activity,
           fp:thread-problems, fp:process-problems.
  Model (docs/deployment.md):
  - a process is an ExecutionEnvironment that is not a thread (as before:
    the one instances are deployed to, its middleware theirs);
  - a model that draws no execution environment: one default process
    per host of its instances (@default, no @middleware; bind/instances.xsl);
  - a thread is an ExecutionEnvironment stereotyped Thread, or, unprofiled,
    one nested in another ExecutionEnvironment whose name ends in 'thread'
    (any case); its process is the nearest enclosing execution environment
    that is no thread; the components deployed on it share its activity
    (Thread tags, else the attributes sample / priority / scheduler /
    cpuAffinity of the thread, else the defaults);
  - a component set is an Artifact stereotyped ComponentSet, or,
    unprofiled, an Artifact that manifests a part; its members are the
    instances of the parts (and components, composite parts) it manifests; a
    Deployment of it on a Node (or in an execution environment of one)
    deploys the set on that host: it gives its members their host and, when
    they are deployed nowhere else, their process (the first execution
    environment of the host); an artifact nested in a node or an execution
    environment is deployed there as by a Deployment;
  - a bus is a CommunicationPath (Bus tags kind, bandwidth).
  Errors: BND024 a thread nested in no process; BND025 an instance in two
  component sets; BND026 two processes of one host with one name.
  Warnings: BND027 an instance's own activity that its thread overrides.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- ======================================================== threads -->
  <xsl:function name="fp:is-thread" as="xs:boolean">
    <xsl:param name="node" as="element(pim:node)"/>
    <xsl:sequence select="$node/@kind eq 'execution-environment'
        and (exists(f:stereotype($node, 'Thread'))
             or (empty(f:stereotype($node, 'Middleware'))
                 and exists($node/ancestor::pim:node[@kind eq 'execution-environment'])
                 and matches($node/@name, 'thread$', 'i')))"/>
  </xsl:function>

  <!-- the process of execution environment $ee: itself, or for a thread the
       nearest enclosing execution environment that is no thread -->
  <xsl:function name="fp:process-of" as="element(pim:node)?">
    <xsl:param name="ee" as="element(pim:node)?"/>
    <xsl:sequence select="if (empty($ee) or not(fp:is-thread($ee))) then $ee
        else $ee/ancestor::pim:node[@kind eq 'execution-environment'][not(fp:is-thread(.))][1]"/>
  </xsl:function>

  <!-- a thread's activity: Thread tags, else its convention attributes,
       else the defaults (sources as for instances) -->
  <xsl:function name="fp:thread-activity" as="element(pim:activity)">
    <xsl:param name="thread" as="element(pim:node)"/>
    <xsl:variable name="values" as="map(*)" select="map:merge(
        for $t in ('period', 'priority', 'scheduler', 'cpuAffinity')
        return map:entry($t, fp:thread-value($thread, $t)))"/>
    <xsl:variable name="id" as="xs:string" select="string($thread/@id)"/>
    <xsl:variable name="sched" as="xs:string"
        select="replace(replace(upper-case(fp:literal(fp:strip($values?scheduler[1]))), '^(ORO_)?SCHED_', ''), '^OTHERS$', 'OTHER')"/>
    <pim:activity period="{fp:quantity($values?period[1], 'period', 'period', fp:holder($values?period, $id))}" period-source="{$values?period[2]}"
                  priority="{fp:integer($values?priority[1], 'priority', fp:holder($values?priority, $id))}" priority-source="{$values?priority[2]}"
                  scheduler="{fp:enum($sched, ('RT', 'OTHER'), 'scheduler', fp:holder($values?scheduler, $id))}" scheduler-source="{$values?scheduler[2]}"
                  cpu-affinity="{fp:integer($values?cpuAffinity[1], 'cpuAffinity', fp:holder($values?cpuAffinity, $id))}" cpu-affinity-source="{$values?cpuAffinity[2]}">
      <xsl:if test="$values?period[3]"><xsl:attribute name="period-holder" select="$values?period[3]"/></xsl:if>
      <xsl:if test="$values?priority[3]"><xsl:attribute name="priority-holder" select="$values?priority[3]"/></xsl:if>
    </pim:activity>
  </xsl:function>

  <!-- (value, source, holder id) of one activity tag of a thread -->
  <xsl:function name="fp:thread-value" as="xs:string+">
    <xsl:param name="thread" as="element(pim:node)"/>
    <xsl:param name="tag" as="xs:string"/>
    <xsl:variable name="conv" as="xs:string" select="if ($tag eq 'period') then 'sample' else $tag"/>
    <xsl:variable name="tagged" as="xs:string?" select="fp:tag($thread, 'Thread', $tag)[normalize-space(.)]"/>
    <xsl:variable name="attribute" as="xs:string?" select="fp:conv($thread, $conv)[normalize-space(.)]"/>
    <xsl:sequence select="
        if (exists($tagged)) then ($tagged, 'stereotype', string(f:stereotype($thread, 'Thread')/@id))
        else if (exists($attribute)) then ($attribute, 'execution-environment', fp:conv-holder($thread, $conv))
        else ((fp:tag-default('Thread', $tag), if ($tag eq 'scheduler') then 'OTHER' else '0')[1], 'default', '')"/>
  </xsl:function>

  <!-- the activity of an instance in thread $thread: the thread's, with
       source "thread"; BND027 when the instance's own differs -->
  <xsl:function name="fp:member-activity" as="element(pim:activity)">
    <xsl:param name="own" as="element(pim:activity)"/>
    <xsl:param name="thread" as="element(pim:node)"/>
    <xsl:param name="instance" as="xs:string"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:variable name="shared" as="element(pim:activity)" select="fp:thread-activity($thread)"/>
    <xsl:variable name="differ" as="xs:string*"
        select="for $a in ('period', 'priority', 'scheduler', 'cpu-affinity')
                return $a[$own/@*[local-name() eq $a || '-source'] = ('stereotype', 'realizing-class')]
                         [string($own/@*[local-name() eq $a]) ne string($shared/@*[local-name() eq $a])]"/>
    <xsl:if test="exists($differ)">
      <xsl:sequence select="f:warn('BND027', $id, 'instance ''' || $instance || ''' runs in thread '''
          || $thread/@name || ''', whose activity it shares: its own '
          || string-join(for $a in $differ return $a || ' ' || $own/@*[local-name() eq $a], ', ')
          || ' give way to the thread''s ' || string-join(for $a in $differ return string($shared/@*[local-name() eq $a]), ', '))"/>
    </xsl:if>
    <pim:activity>
      <xsl:for-each select="$shared/@*">
        <xsl:attribute name="{local-name()}" select="if (ends-with(local-name(), '-source')) then 'thread' else string(.)"/>
      </xsl:for-each>
    </pim:activity>
  </xsl:function>

  <!-- ================================================ component sets -->
  <!-- the component sets by id, each artifact decided once: an artifact
       holds a child per manifestation, so deciding it on every call
       (f:stereotype reads its children) made the binding quadratic in the
       components one artifact manifests -->
  <xsl:key name="fp:component-set" match="pim:artifact[fp:artifact-is-set(.)]" use="string(@id)"/>

  <xsl:function name="fp:is-set" as="xs:boolean">
    <xsl:param name="artifact" as="element(pim:artifact)"/>
    <xsl:sequence select="exists(key('fp:component-set', string($artifact/@id), root($artifact)))"/>
  </xsl:function>

  <xsl:function name="fp:artifact-is-set" as="xs:boolean">
    <xsl:param name="artifact" as="element(pim:artifact)"/>
    <xsl:sequence select="exists(f:stereotype($artifact, 'ComponentSet'))
        or (empty(f:stereotype($artifact, 'Library'))
            and exists(key('fp:manifests-part', string($artifact/@id), root($artifact))))"/>
  </xsl:function>

  <!-- true when deployment $d deploys component sets only -->
  <xsl:function name="fp:set-deployment" as="xs:boolean">
    <xsl:param name="deployment" as="element(pim:deployment)"/>
    <xsl:variable name="deployed" as="element()*"
        select="tokenize($deployment/@deployed) ! key('fp:id', ., root($deployment))"/>
    <xsl:sequence select="exists($deployed) and (every $e in $deployed satisfies ($e/self::pim:artifact and fp:is-set($e)))"/>
  </xsl:function>

  <!-- the component sets that hold the element ids $ids (a part, its
       component, the composite parts around it) -->
  <xsl:function name="fp:sets-of" as="element(pim:artifact)*">
    <xsl:param name="ids" as="xs:string*"/>
    <xsl:param name="root" as="document-node()"/>
    <xsl:sequence select="key('fp:manifestation-by-element', $ids, $root)/..[fp:is-set(.)]"/>
  </xsl:function>

  <xsl:function name="fp:component-sets" as="element(pim:component-set)*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:param name="hosts" as="element(pim:node)*"/>
    <xsl:for-each select="$model/pim:platform//pim:artifact[fp:is-set(.)]">
      <pim:component-set xmi-id="{@id}" name="{f:cpp-identifier(@name)}">
        <xsl:for-each select="key('fp:deployment-by-deployed', @id, root($model))">
          <xsl:variable name="host" as="element(pim:node)?" select="fp:host-of(fp:deployment-ee(.), .., $hosts)"/>
          <pim:on deployment="{@id}">
            <xsl:if test="$host"><xsl:attribute name="host" select="$host/@id"/></xsl:if>
          </pim:on>
        </xsl:for-each>
        <!-- an artifact nested in a node (or an execution environment of
             one) is deployed there: @deployment is the artifact's own id -->
        <xsl:variable name="artifact" as="element(pim:artifact)" select="."/>
        <xsl:for-each select="@node/key('fp:id', ., root($model))[self::pim:node]">
          <xsl:variable name="host" as="element(pim:node)?"
              select="fp:host-of(fp:owner-ee($artifact), ancestor-or-self::pim:node, $hosts)"/>
          <pim:on deployment="{$artifact/@id}">
            <xsl:if test="$host"><xsl:attribute name="host" select="$host/@id"/></xsl:if>
          </pim:on>
        </xsl:for-each>
      </pim:component-set>
    </xsl:for-each>
  </xsl:function>

  <!-- ====================================================== processes -->
  <!-- one pim:process per execution environment that holds an instance,
       in model order, with its threads that hold one -->
  <xsl:function name="fp:processes" as="element(pim:process)*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="hosts" as="element(pim:node)*"/>
    <xsl:variable name="root" as="document-node()" select="root($model)"/>
    <!-- execution environment id -> its instances, in one pass (not a scan
         of every instance per environment) -->
    <xsl:variable name="by-environment" as="map(xs:string, element(pim:instance)+)">
      <xsl:map>
        <xsl:for-each-group select="$instances" group-by="@execution-environment">
          <xsl:map-entry key="string(current-grouping-key())" select="current-group()"/>
        </xsl:for-each-group>
      </xsl:map>
    </xsl:variable>
    <xsl:for-each select="fp:execution-environments($root)[@id ! map:contains($by-environment, string(.))]">
      <xsl:variable name="mine" as="element(pim:instance)+" select="$by-environment(string(@id))"/>
      <xsl:variable name="managed" as="xs:string?" select="fp:tag(., 'Middleware', 'managed')[normalize-space(.)]"/>
      <pim:process xmi-id="{@id}" name="{f:name-identifier(@name)}" middleware="{$mine[1]/@middleware}"
                   managed="{if (exists($managed)) then fp:boolean($managed, 'managed', string(@id)) else false()}">
        <xsl:sequence select="$mine[1]/@host"/>
        <!-- its threads, in model order: by key, not a scan of every environment per process -->
        <xsl:for-each select="key('fp:id', distinct-values($mine/@thread), $root)
                              [self::pim:node[@kind eq 'execution-environment']]
                              [ancestor::pim:platform[parent::pim:model/parent::document-node()]]">
          <pim:thread xmi-id="{@id}" name="{f:cpp-identifier(@name)}">
            <xsl:sequence select="fp:thread-activity(.)"/>
          </pim:thread>
        </xsl:for-each>
      </pim:process>
    </xsl:for-each>
    <!-- the default processes of a model that draws no execution
         environment, one per host (BND028): no middleware, each target
         deploys them on its own; named after the model (with the host's
         name when there are several); managed when every component in it
         is one its tool runs as a managed node (pim:component/@managed:
         Papyrus for Robotics) -->
    <xsl:variable name="undrawn" as="element(pim:instance)*" select="$instances[empty(@middleware)]"/>
    <xsl:variable name="several" as="xs:boolean" select="count(distinct-values($undrawn/@host)) gt 1"/>
    <xsl:for-each-group select="$undrawn" group-by="string(@host)">
      <pim:process xmi-id="{current-grouping-key()}"
                   name="{f:cpp-identifier(string-join(($model/@name, key('fp:id', current-grouping-key(), $root)[self::pim:node]/@name[$several]), '_'))}"
                   host="{current-grouping-key()}"
                   managed="{every $i in current-group() satisfies key('fp:id', $i/@component, $root)/@managed = 'true'}"
                   default="true"/>
    </xsl:for-each-group>
  </xsl:function>

  <!-- ========================================================== buses -->
  <xsl:function name="fp:links" as="element(pim:link)*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:param name="hosts" as="element(pim:node)*"/>
    <xsl:for-each select="$model/pim:platform/pim:communication-path">
      <xsl:variable name="kind" as="xs:string?" select="fp:tag(., 'Bus', 'kind')[normalize-space(.)]"/>
      <xsl:variable name="bandwidth" as="xs:string?" select="fp:tag(., 'Bus', 'bandwidth')[normalize-space(.)]"/>
      <pim:link xmi-id="{@id}" name="{@name}"
                kind="{if (exists($kind)) then fp:literal($kind) else if (exists(f:stereotype(., 'Bus'))) then fp:tag-default('Bus', 'kind') else 'unspecified'}">
        <!-- a bandwidth with a unit, or Mbit/s (fp:quantity), in Mbit/s -->
        <xsl:variable name="mbits" as="xs:double?"
            select="$bandwidth ! fp:quantity(., 'bandwidth', 'bandwidth', string(f:stereotype(current(), 'Bus')/@id))"/>
        <xsl:if test="$mbits gt 0">
          <xsl:attribute name="bandwidth" select="$mbits"/>
        </xsl:if>
        <xsl:for-each select="pim:end">
          <xsl:variable name="node" as="element(pim:node)?" select="key('fp:id', @node, root($model))[self::pim:node]"/>
          <pim:link-end node="{@node}">
            <xsl:for-each select="($node/ancestor-or-self::pim:node intersect $hosts)[last()]">
              <xsl:attribute name="host" select="@id"/>
            </xsl:for-each>
          </pim:link-end>
        </xsl:for-each>
      </pim:link>
    </xsl:for-each>
  </xsl:function>

  <!-- ======================================================= problems -->
  <!-- BND024 threads in no process -->
  <xsl:function name="fp:thread-problems" as="map(*)*">
    <xsl:param name="root" as="document-node()"/>
    <xsl:sequence select="fp:execution-environments($root)[fp:is-thread(.)][empty(fp:process-of(.))]
        ! map { 'code': 'BND024', 'id': string(@id), 'message': 'thread ''' || @name
                || ''' is nested in no execution environment: a thread belongs to a process; nest it in the process''s ExecutionEnvironment' }"/>
  </xsl:function>

  <!-- BND026 processes of one host with one name -->
  <xsl:function name="fp:process-problems" as="map(*)*">
    <xsl:param name="root" as="document-node()"/>
    <xsl:param name="processes" as="element(pim:process)*"/>
    <xsl:for-each-group select="$processes" group-by="@host || '|' || @name">
      <xsl:if test="count(current-group()) gt 1">
        <xsl:sequence select="map { 'code': 'BND026', 'id': string(current-group()[2]/@xmi-id), 'message':
            'host ''' || key('fp:id', current-group()[1]/@host, $root)/@name || ''' has ' || count(current-group())
            || ' processes named ''' || current-group()[1]/@name || ''': their deployment files would have one name; rename one' }"/>
      </xsl:if>
    </xsl:for-each-group>
  </xsl:function>
</xsl:stylesheet>
