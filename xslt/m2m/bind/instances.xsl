<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/instances.xsl - bind (xslt/m2m/bind.xsl): hosts, atomic-code libraries and component instances with their activities.

  Reads:   the PIM (urn:robomda:pim:1) and the working trees of fp:binding.
  Writes:  parts of pim:binding (schemas/pim/1/binding.xsd), or values.
  Params:  none.  Keys: those of bind.xsl.
  Provides: fp:host, fp:default-host, fp:libraries, fp:instance, fp:instance-ee,
           fp:owner-ee, fp:owner-nodes, fp:draws-no-process, fp:activity, fp:activity-value,
           fp:holder.
  Placement: an instance runs in the execution environment a Deployment
           gives it (of its part, component, enclosing composites, realizing
           class, or an artifact that manifests one of them), else the one
           that owns its component in the XMI, else the one that owns an
           artifact manifesting it (an Artifact nested in a Node or an
           ExecutionEnvironment), else the model's only one. A model that
           draws no execution environment at all (the first component model
           a developer draws) runs every instance in one default process
           per host (@default, no @middleware: each target deploys it on
           its own middleware), on the Node its deployment or owner gives,
           else the model's only Node, else a default host (localhost,
           127.0.0.1); bind.xsl warns once (BND028). A model that draws
           execution environments but deploys an instance in none keeps
           BND006: the platform is drawn, the instance was left out of it.
  Errors:  BND006 an instance deployed to no execution environment while the
           model has several; BND010.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:m="urn:robomda:xslt:mode"
    xmlns:t="urn:robomda:xslt:template"
    xmlns:mp="urn:robomda:xslt:mode:private"
    xmlns:err="http://www.w3.org/2005/xqt-errors"
    exclude-result-prefixes="#all">

  <!-- ========================================================== hosts -->
  <xsl:function name="fp:host" as="element(pim:host)">
    <xsl:param name="node" as="element(pim:node)"/>
    <xsl:param name="host-count" as="xs:integer"/>
    <xsl:variable name="hn" as="xs:string?" select="fp:tag($node, 'Host', 'hostname')[normalize-space(.)]"/>
    <xsl:variable name="ad" as="xs:string?" select="fp:tag($node, 'Host', 'address')[normalize-space(.)]"/>
    <xsl:variable name="hostname" as="xs:string" select="($hn, string($node/@name))[1]"/>
    <pim:host xmi-id="{$node/@id}" name="{$node/@name}" hostname="{$hostname}"
              hostname-source="{if (exists($hn)) then 'stereotype' else 'name'}"
              address="{if (exists($ad)) then $ad else if ($host-count eq 1) then 'localhost' else $hostname}"
              address-source="{if (exists($ad)) then 'stereotype' else 'default'}"
              real-time="{fp:host-real-time($node)}" described="{exists(f:stereotype($node, 'Host'))}">
      <!-- the computational resources, where the model gives them (seed 002) -->
      <!-- memory: a size with a unit or MiB (fp:mebibytes), in MiB -->
      <xsl:for-each select="'cores', 'memory'">
        <xsl:variable name="value" as="xs:string?" select="(fp:tag($node, 'Host', .), fp:conv($node, .))[normalize-space(.)][1]"/>
        <!-- an error points at the Host stereotype application, or the attribute -->
        <xsl:variable name="holder" as="xs:string"
            select="if (exists(fp:tag($node, 'Host', .)[normalize-space(.)])) then string(f:stereotype($node, 'Host')/@id)
                    else (fp:conv-holder($node, .)[. ne ''], string($node/@id))[1]"/>
        <xsl:variable name="number" as="xs:integer?"
            select="if (empty($value)) then () else if (. eq 'memory') then fp:mebibytes($value, ., $holder)
                    else fp:integer($value, ., $holder)"/>
        <xsl:if test="exists($number) and $number gt 0">
          <xsl:attribute name="{.}" select="$number"/>
        </xsl:if>
      </xsl:for-each>
    </pim:host>
  </xsl:function>

  <!-- true when host $node runs a real-time kernel: Host tag realTime, else
       its attribute realTime -->
  <xsl:function name="fp:host-real-time" as="xs:boolean">
    <xsl:param name="node" as="element(pim:node)"/>
    <xsl:variable name="value" as="xs:string?" select="(fp:tag($node, 'Host', 'realTime'), fp:conv($node, 'realTime'))[normalize-space(.)][1]"/>
    <xsl:sequence select="exists($value) and fp:boolean($value, 'realTime', string($node/@id))"/>
  </xsl:function>

  <!-- the default host of the default process (BND028): the model draws
       no execution environment and the instance no Node; its id is the
       model's -->
  <xsl:function name="fp:default-host" as="element(pim:host)">
    <xsl:param name="model" as="element(pim:model)"/>
    <pim:host xmi-id="{$model/@id}" name="localhost" hostname="localhost" hostname-source="default"
              address="127.0.0.1" address-source="default" real-time="false" described="false" default="true"/>
  </xsl:function>

  <!-- ====================================================== libraries -->
  <xsl:function name="fp:libraries" as="element(pim:library)*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:variable name="all" as="element(pim:artifact)*" select="$model/pim:platform//pim:artifact[not(fp:is-set(.))]"/>
    <xsl:variable name="profiled" as="element(pim:artifact)*" select="$all[exists(f:stereotype(., 'Library'))]"/>
    <xsl:for-each select="if (exists($profiled)) then $profiled else $all">
      <xsl:variable name="item" as="xs:string?" select="fp:tag(., 'Library', 'path')[normalize-space(.)]"/>
      <xsl:variable name="type" as="xs:string?" select="fp:tag(., 'Library', 'target')[normalize-space(.)]"/>
      <xsl:variable name="instance" as="xs:string?" select="fp:tag(., 'Library', 'includeDir')[normalize-space(.)]"/>
      <xsl:variable name="path" as="xs:string"
          select="translate(($item, @file-name[normalize-space(.)], @name)[1], '\', '/')"/>
      <pim:library xmi-id="{@id}" name="{@name}" path="{$path}"
                   path-source="{if (exists($item)) then 'stereotype' else if (normalize-space(@file-name)) then 'file-name' else 'name'}"
                   absolute="{starts-with($path, '/') or matches($path, '^[A-Za-z]:/')}"
                   target="{($type, @name)[1]}"
                   target-source="{if (exists($type)) then 'stereotype' else 'name'}"
                   include-dir="{($instance, 'include')[1]}">
        <xsl:for-each select="pim:manifestation">
          <pim:manifests element="{@element}"/>
        </xsl:for-each>
      </pim:library>
    </xsl:for-each>
  </xsl:function>

  <!-- ====================================================== instances -->
  <xsl:function name="fp:instance" as="element(pim:instance)">
    <xsl:param name="part" as="element(pim:part)?"/>
    <xsl:param name="component" as="element(pim:component)"/>
    <!-- the unit of the expansion (bind/composites.xsl), when instances
         come from parts -->
    <xsl:param name="unit" as="element(fp:unit)?"/>
    <xsl:param name="ees" as="element(pim:node)*"/>
    <xsl:param name="hosts" as="element(pim:node)*"/>
    <!-- the name, when the component's own would be shared (components of
         one name in different packages: their qualified names) -->
    <xsl:param name="qualified" as="xs:string?"/>
    <xsl:variable name="root" as="document-node()" select="root($component)"/>
    <xsl:variable name="realization-item" as="element(pim:class)?" select="fp:realizing-class($component)"/>
    <xsl:variable name="around" as="xs:string*" select="tokenize($unit/@around)"/>
    <xsl:variable name="deployments" as="element(pim:deployment)*"
        select="fp:deployments-of($part, $component, $around, $realization-item)"/>
    <xsl:variable name="ids" as="xs:string*" select="($part/@id, $component/@id, $around, $realization-item/@id) ! string(.)"/>
    <!-- the execution environment deployed to: a process, or a thread of one -->
    <xsl:variable name="target" as="element(pim:node)?" select="fp:ee-of($deployments, $component, $ids, $ees)"/>
    <xsl:variable name="thread" as="element(pim:node)?" select="$target[fp:is-thread(.)]"/>
    <xsl:variable name="ee" as="element(pim:node)?" select="fp:process-of($target)"/>
    <xsl:variable name="inst-id" as="xs:string" select="string(($part/@id, $component/@id)[1])"/>
    <xsl:variable name="sets" as="element(pim:artifact)*" select="fp:sets-of(($part/@id, $component/@id, $around), $root)"/>
    <xsl:if test="count($sets) gt 1">
      <xsl:sequence select="f:fail('BND025', $inst-id, 'instance ''' || ($unit/@name, $part/@name, $component/@name)[1]
          || ''' is in ' || count($sets) || ' component sets (''' || string-join($sets/@name, ''', ''')
          || '''): an instance belongs to at most one set')"/>
    </xsl:if>
    <!-- no execution environment drawn at all: the default process -->
    <xsl:variable name="undrawn" as="xs:boolean" select="empty($ee) and fp:draws-no-process($root)"/>
    <xsl:if test="empty($ee) and not($undrawn)">
      <xsl:sequence select="f:fail-all(fp:no-ee-problem($part, $component, $ees))"/>
    </xsl:if>
    <xsl:variable name="host" as="element(pim:node)?"
        select="(fp:host-of($ee, $deployments/.., $hosts), fp:owner-nodes($ids, $root) intersect $hosts,
                 if (count($hosts) eq 1) then $hosts else ())[1]"/>
    <!-- the default process's id: its host's (a Node, else the model) -->
    <xsl:variable name="host-id" as="xs:string?" select="($host/@id, $root/pim:model/@id[$undrawn])[1]"/>
    <pim:instance name="{($unit/@name, $qualified, f:cpp-identifier(($part/@name[normalize-space(.)], $component/@name)[1]))[1]}"
                  xmi-id="{$inst-id}" component="{$component/@id}">
      <xsl:if test="$unit"><xsl:attribute name="composite" select="$unit/@top"/></xsl:if>
      <!-- inside a composite part: where in the hierarchy -->
      <xsl:if test="$unit/@parent">
        <xsl:sequence select="$unit/(@path, @parent)"/>
      </xsl:if>
      <xsl:if test="exists($host-id)"><xsl:attribute name="host" select="$host-id"/></xsl:if>
      <xsl:attribute name="execution-environment" select="if ($undrawn) then $host-id else $ee/@id"/>
      <xsl:if test="$thread"><xsl:attribute name="thread" select="$thread/@id"/></xsl:if>
      <xsl:if test="$sets"><xsl:attribute name="set" select="$sets/@id"/></xsl:if>
      <xsl:if test="exists($ee)"><xsl:attribute name="middleware" select="fp:middleware($ee)"/></xsl:if>
      <xsl:for-each select="fp:tag($ee, 'Middleware', 'version')[normalize-space(.)]">
        <xsl:attribute name="middleware-version" select="."/>
      </xsl:for-each>
      <xsl:if test="$realization-item"><xsl:attribute name="realization" select="$realization-item/@id"/></xsl:if>
      <!-- only the elements with an Activity stereotype can give a tag -->
      <xsl:variable name="own" as="element(pim:activity)"
          select="fp:activity(($part, $component, $realization-item)[exists(f:stereotype(., 'Activity'))], $realization-item, $ee, $inst-id)"/>
      <!-- in a thread: the thread's activity (bind/runtime.xsl) -->
      <xsl:sequence select="if ($thread) then fp:member-activity($own, $thread, ($unit/@name, $part/@name, $component/@name)[1], $inst-id) else $own"/>
      <!-- values set by the enclosing parts and composites (seed 003) -->
      <xsl:sequence select="fp:property-values($part, $around, fp:feature-owner($component))"/>
      <!-- every deployment that reaches the instance, so the deployment
           rules (schemas/pim/1/pim.sch) can see one deployed twice -->
      <xsl:for-each select="$deployments[not(fp:set-deployment(.))]">
        <xsl:variable name="d-ee" as="element(pim:node)?" select="fp:process-of(fp:deployment-ee(.))"/>
        <xsl:variable name="d-host" as="element(pim:node)?" select="fp:host-of($d-ee, .., $hosts)"/>
        <pim:deployed-on deployment="{@id}">
          <xsl:if test="$d-ee"><xsl:attribute name="execution-environment" select="$d-ee/@id"/></xsl:if>
          <xsl:if test="$d-host"><xsl:attribute name="host" select="$d-host/@id"/></xsl:if>
        </pim:deployed-on>
      </xsl:for-each>
    </pim:instance>
  </xsl:function>

  <!-- the deployments that place the instance of $part (or of component
       $component): of the part, the component, the enclosing composites and
       composite parts ($around: ids), the realizing class, or an artifact
       that manifests one of them -->
  <xsl:function name="fp:deployments-of" as="element(pim:deployment)*">
    <xsl:param name="part" as="element(pim:part)?"/>
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:param name="around" as="xs:string*"/>
    <xsl:param name="realization" as="element(pim:class)?"/>
    <xsl:variable name="root" as="document-node()" select="root($component)"/>
    <xsl:variable name="ids" as="xs:string*" select="($part/@id, $component/@id, $around, $realization/@id) ! string(.)"/>
    <xsl:variable name="artifact-ids" as="xs:string*"
        select="key('fp:manifestation-by-element', $ids, $root)/../@id ! string(.)"/>
    <xsl:sequence select="key('fp:deployment-by-deployed', ($ids, $artifact-ids), $root)"/>
  </xsl:function>

  <!-- the execution environment of the instance of $part (or of
       component $c when instances come from components), as fp:instance
       finds it: a process, or a thread of one -->
  <xsl:function name="fp:instance-ee" as="element(pim:node)?">
    <xsl:param name="part" as="element(pim:part)?"/>
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:param name="around" as="xs:string*"/>
    <xsl:param name="ees" as="element(pim:node)*"/>
    <xsl:variable name="realization" as="element(pim:class)?" select="fp:realizing-class($component)"/>
    <xsl:sequence select="fp:ee-of(fp:deployments-of($part, $component, $around, $realization), $component,
                                   ($part/@id, $component/@id, $around, $realization/@id) ! string(.), $ees)"/>
  </xsl:function>

  <!-- the execution environment of an instance of $component placed by
       $deployments: the first they reach (deployments of component sets
       last: a set gives the host, its members may choose the process),
       else the one that owns the component, else the one that owns an
       artifact manifesting the instance ($ids: its part, component,
       enclosing composites, realizing class), else the model's only one -->
  <xsl:function name="fp:ee-of" as="element(pim:node)?">
    <xsl:param name="deployments" as="element(pim:deployment)*"/>
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:param name="ids" as="xs:string*"/>
    <xsl:param name="ees" as="element(pim:node)*"/>
    <xsl:sequence select="(($deployments[not(fp:set-deployment(.))], $deployments[fp:set-deployment(.)]) ! fp:deployment-ee(.),
                           fp:owner-ee($component),
                           key('fp:manifestation-by-element', $ids, root($component))/..[@node] ! fp:owner-ee(.),
                           if (count($ees) eq 1) then $ees else ())[1]"/>
  </xsl:function>

  <!-- the execution environment of the node that owns component or
       artifact $e in the XMI (EA nests a component in the node it runs
       on, an artifact in the environment it is deployed in): the node
       itself, else the first one nested in it -->
  <xsl:function name="fp:owner-ee" as="element(pim:node)?">
    <xsl:param name="e" as="element()"/>
    <xsl:variable name="node" as="element(pim:node)?" select="$e/@node ! key('fp:id', ., root($e))[self::pim:node]"/>
    <xsl:sequence select="($node[@kind eq 'execution-environment'], $node//pim:node[@kind eq 'execution-environment'])[1]"/>
  </xsl:function>

  <!-- the nodes that own, in the XMI, the elements $ids (a component) or
       an artifact that manifests one of them, and the nodes around those -->
  <xsl:function name="fp:owner-nodes" as="element(pim:node)*">
    <xsl:param name="ids" as="xs:string*"/>
    <xsl:param name="root" as="document-node()"/>
    <xsl:sequence select="(key('fp:id', $ids, $root), key('fp:manifestation-by-element', $ids, $root)/..)/@node
                          ! key('fp:id', ., $root)[self::pim:node]/ancestor-or-self::pim:node"/>
  </xsl:function>

  <!-- true when the model draws no execution environment at all: its
       instances run in default processes (BND028) -->
  <xsl:function name="fp:draws-no-process" as="xs:boolean">
    <xsl:param name="root" as="document-node()"/>
    <xsl:sequence select="empty(fp:execution-environments($root))"/>
  </xsl:function>

  <!-- BND006 about the instance of $part / $c (the model draws
       execution environments, $ees: one or several) -->
  <xsl:function name="fp:no-ee-problem" as="map(*)">
    <xsl:param name="part" as="element(pim:part)?"/>
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:param name="ees" as="element(pim:node)*"/>
    <xsl:sequence select="map { 'code': 'BND006', 'id': string(($part/@id, $component/@id)[1]), 'message':
        'component instance ''' || ($part/@name, $component/@name)[1] || ''' is deployed to no execution environment'
        || ' and the model has ' || count($ees) || ' of them (' || string-join($ees ! ('''' || @name || ''''), ', ')
        || '): draw a Deployment of the part (or of its component, or of an artifact that manifests it) on one,'
        || ' or nest the component, or an artifact that manifests it, in one (docs/profile.md)' }"/>
  </xsl:function>

  <!-- the execution environment deployment $d reaches: its target, else
       the first one nested in its target -->
  <xsl:function name="fp:deployment-ee" as="element(pim:node)?">
    <xsl:param name="deployment" as="element(pim:deployment)"/>
    <xsl:sequence select="if ($deployment/../@kind eq 'execution-environment') then $deployment/..
                          else ($deployment/..//pim:node[@kind eq 'execution-environment'])[1]"/>
  </xsl:function>

  <!-- the host of execution environment $ee (the nearest enclosing node
       among $hosts), else the first of the deployment targets $targets that
       is a host ($hosts: fp:hosts; each node is tested with fp:is-host, the
       same set, so that no instance scans every host) -->
  <xsl:function name="fp:host-of" as="element(pim:node)?">
    <xsl:param name="ee" as="element(pim:node)?"/>
    <xsl:param name="targets" as="element()*"/>
    <xsl:param name="hosts" as="element(pim:node)*"/>
    <xsl:sequence select="($ee/ancestor::pim:node[fp:is-host(.)][1], $targets[fp:is-host(.)])[1]"/>
  </xsl:function>

  <!-- one activity value: (value, source) from stereotype tag, class
       convention, EE convention or default -->
  <!-- (value, where it comes from, the id of the element that holds it or
       '' for a default): the value sits on an Activity stereotype
       application, a convention attribute of the realizing class or of the
       execution environment; errors about it point at that element -->
  <xsl:function name="fp:activity-value" as="xs:string+">
    <xsl:param name="stereo-on" as="element()*"/>
    <xsl:param name="tag" as="xs:string"/>
    <xsl:param name="realization" as="element(pim:class)?"/>
    <xsl:param name="ee" as="element(pim:node)?"/>
    <xsl:param name="conv" as="xs:string"/>
    <xsl:param name="default" as="xs:string"/>
    <xsl:variable name="type" as="xs:string?" select="fp:first-tag($stereo-on, 'Activity', $tag)"/>
    <xsl:variable name="classifier" as="xs:string?" select="fp:conv($realization, $conv)[normalize-space(.)]"/>
    <xsl:variable name="element" as="xs:string?"
        select="if ($conv eq 'sample') then () else fp:conv($ee, $conv)[normalize-space(.)]"/>
    <xsl:sequence select="if (exists($type)) then ($type, 'stereotype',
                              string(($stereo-on ! f:stereotype(., 'Activity'))[f:stereotype-tag(., $tag)[normalize-space(@value)]][1]/@id))
                          else if (exists($classifier)) then ($classifier, 'realizing-class', fp:conv-holder($realization, $conv))
                          else if (exists($element)) then ($element, 'execution-environment', fp:conv-holder($ee, $conv))
                          else ($default, 'default', '')"/>
  </xsl:function>

  <xsl:function name="fp:activity" as="element(pim:activity)">
    <xsl:param name="stereo-on" as="element()*"/>
    <xsl:param name="realization" as="element(pim:class)?"/>
    <xsl:param name="ee" as="element(pim:node)?"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:variable name="period" as="xs:string+" select="fp:activity-value($stereo-on, 'period', $realization, $ee, 'sample', '0')"/>
    <xsl:variable name="prio" as="xs:string+" select="fp:activity-value($stereo-on, 'priority', $realization, $ee, 'priority', '0')"/>
    <xsl:variable name="sched" as="xs:string+" select="fp:activity-value($stereo-on, 'scheduler', $realization, $ee, 'scheduler', 'OTHER')"/>
    <xsl:variable name="cpu" as="xs:string+" select="fp:activity-value($stereo-on, 'cpuAffinity', $realization, $ee, 'cpuAffinity', '0')"/>
    <xsl:variable name="text" as="xs:string"
        select="replace(replace(upper-case(fp:literal(fp:strip($sched[1]))), '^(ORO_)?SCHED_', ''), '^OTHERS$', 'OTHER')"/>
    <pim:activity period="{fp:quantity($period[1], 'period', 'period', fp:holder($period, $id))}" period-source="{$period[2]}"
                  priority="{fp:integer($prio[1], 'priority', fp:holder($prio, $id))}" priority-source="{$prio[2]}"
                  scheduler="{fp:enum($text, ('RT', 'OTHER'), 'scheduler', fp:holder($sched, $id))}" scheduler-source="{$sched[2]}"
                  cpu-affinity="{fp:integer($cpu[1], 'cpuAffinity', fp:holder($cpu, $id))}" cpu-affinity-source="{$cpu[2]}">
      <xsl:if test="$period[3]"><xsl:attribute name="period-holder" select="$period[3]"/></xsl:if>
      <xsl:if test="$prio[3]"><xsl:attribute name="priority-holder" select="$prio[3]"/></xsl:if>
    </pim:activity>
  </xsl:function>

  <!-- the element an error about an fp:activity-value points at: the one
       that holds the value, else $fallback -->
  <xsl:function name="fp:holder" as="xs:string">
    <xsl:param name="value" as="xs:string+"/>
    <xsl:param name="fallback" as="xs:string"/>
    <xsl:sequence select="($value[3][. ne ''], $fallback)[1]"/>
  </xsl:function>
</xsl:stylesheet>
