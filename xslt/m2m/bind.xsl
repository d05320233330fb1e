<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind.xsl - resolve the platform binding of a PIM.

  Reads:   a PIM, urn:robomda:pim:1 (schemas/pim/1/pim.xsd), as written by
           xslt/import/import.xsl; an existing pim:binding is replaced.
  Writes:  the same PIM with pim:binding appended (schemas/pim/1/binding.xsd),
           indented as f:indent (common/indent.xsl) indents it; a model with
           element-only content is indented in the same pass, through
           f:indent's own rules (t:indented-content), with no copy of it first;
           the parts of it that are indented already (as import.xsl writes
           them: f:indented) are copied whole.
  Params:  none.
  Modules: by concern, in bind/: values.xsl (tags and value parsing),
           lookups.xsl (realizing classes, middlewares, hosts),
           instances.xsl (hosts, libraries, instances, activities),
           ports.xsl (bound components, data ports), connections.xsl
           (connection points and policies), sequence.xsl (deployment
           sequence), composites.xsl (composites of any depth flattened,
           connector ends resolved through delegations), jobs.xsl (jobs
           and subsystems: JOB001-JOB009, JOB030). This file: the keys, the entry, the reference checks
           and fp:binding, which puts the binding together.

  Classes taken as components (bind/classes.xsl, docs/profile.md,
  "Components drawn as classes"): a class that its tool's profile makes a
  component (pim:class/@component), or that has ports and types a part, or
  whose parts are typed by components, is bound as a component: the model
  is first copied with each such class written as a pim:component
  (@drawn-as="class"), then bound as below.

  What it resolves (docs/profile.md: stereotypes of profile "robomda" first,
  else the unprofiled conventions of seed 000, else defaults):
  - instances: when a composite component has parts typed by components and
    is not itself the type of a part ("top composite"), the parts of all top
    composites are the instances and their assembly connectors the
    connections; a part typed by a composite is no instance but contributes
    its own parts, at any depth, named by their path (bind/composites.xsl:
    pim:composite-instance, pim:instance/@path, @parent), and the assembly
    connectors of each composite part are connections too, their ends on a
    composite's port resolved through its delegation connectors; otherwise one instance per non-abstract component that has
    ports or a realization and is no «Alternative» (a component that may
    replace another, checked by xslt/check/substitute.xsl, is not part of
    the system until a part is typed by it), named after the component. Instance names are
    made valid C++ identifiers (xslt/common/naming.xsl).
  - per instance: execution environment (the ExecutionEnvironment that the
    part, component, top composite, realizing class, or an artifact that
    manifests one of them, is deployed to; else the only one of the model),
    its middleware (Middleware::kind, else the EE name), host (the enclosing
    Node, else the node holding the deployment, else the only host), and
    activity (Activity tags on part > component > realizing class; else the
    attributes sample / priority / scheduler / cpuAffinity of the realizing
    class; priority / scheduler / cpuAffinity also of the EE; else 0 / 0 /
    OTHER / 0).
  - per component type: realizing class (+ AtomicCode header / cppName) and
    data ports. A port's interfaces: its explicit provided / required lists;
    else, typed by an interface: "in" when the component or its realizing
    class requires (Usage) it, "out" when it provides it, else "out"
    ("in" if the port is conjugated); typed by a class: the interfaces that
    class provides (out) and requires (in), swapped if conjugated. The datum
    is the one attribute of the interface. Typed by a data type (datatype,
    primitive, enumeration of the model, or a library primitive): one data
    port, "out" ("in" if conjugated), whose datum is the port itself.
  - connections: connector mode groups connector writer->reader pairs by
    writer port (one connection point per output port); ball-and-socket mode
    makes one connection point per interface with all its writers and
    readers. Name: the (first) connector's name, else <Interface>Conn, made a
    unique identifier. Policy: ConnectionPolicy on the connector > writer port
    > reader port > interface > default DATA / 1 / LOCK_FREE / init false /
    pull false / topic "".
  - libraries (Artifacts stereotyped Library; if none is, every Artifact):
    path (Library::path > fileName > name), target (Library::target > name),
    includeDir (Library::includeDir > "include").
  - hosts: Nodes, and Nodes / Devices stereotyped Host; hostname (Host tag >
    name), address (Host tag > "localhost" when the model has one host, else
    the hostname).
  - deployment sequence (seed 002, "A before B"): every pim:dependency
    stereotyped StartAfter (else named startAfter, case-insensitive) says
    that each of its clients starts after each of its suppliers; clients and
    suppliers must be instances (the parts that became instances, or the
    components when instances come from components). Each instance lists
    its constraints (pim:start-after: the earlier instance and the
    dependency) and gets @start-order, its 1-based position in a
    topological order of all instances: Kahn's algorithm, taking among the
    instances ready to start the first in document order (so an instance
    without constraints keeps its relative place, and a model without
    constraints keeps the document order). Instances on a cycle, or after
    one, get no @start-order (no error here: the constraint checks report
    them). Cost: keys for every look-up; the ready set is the instances
    with no constraint, consumed in order, plus a sorted list of those
    released by their last constraint.

  Errors (namespace urn:robomda:error, raised with f:fail; every BND001 /
  BND002 of the model, every BND006 / BND003 of the instances, every
  BND009 and every port problem (BND002, BND005, BND030) of the
  instantiated components at once, with f:fail-all):
    BND001  dangling reference: an id attribute points to no PIM element
    BND002  a port is typed by, provides or requires a missing interface
    BND003  unknown middleware name (names the ExecutionEnvironment); a
            Middleware stereotype without kind means the profile default
            (xslt/import/profile-defaults.xml: OROCOS)
    BND004  (warning, bind/ports.xsl) an interface used by a port carries no
            datum (no attribute) and no operation: the port is left out
    BND005  an interface used by a port carries several data (attributes)
    BND006  an instance is deployed to no execution environment and the model
            has several (a model with none runs every instance in a default
            process: BND028)
    BND007  a connector joins no output port to an input port of the same
            data type
    BND008  an input port is fed by several connection points (connector mode)
    BND009  two instances get the same name
    BND010  invalid tag / convention value (period, priority, scheduler,
            cpuAffinity, connection type, size, lock policy, boolean)
    BND011  a realizing class has no usable C++ name (unnamed, or a bad
            AtomicCode cppName)
    BND012  a StartAfter dependency whose client or supplier is not a
            component instance (a part that became an instance, or the
            component in a model without composites); names the dependency
    BND013  a composite is a part of itself at any depth (each composite on
            the cycle; raised before anything else is bound)
    BND014  a connector reaches a promoted port that its composite
            delegates to nothing
    BND015  a delegation joins ports that do not carry the same data in the
            same direction
    BND035  a composite's own behaviour port (UML-RT) joined to its part
    BND016  (warning) a property of a composite promotes the property of no part
    BND017  a property of a composite names the properties of several parts
    BND018  a part sets a value on a property its type does not have
    BND030  a port's direction in its tool's profile is none of in, out,
            inout (bind/ports.xsl)
  Notes: SUB030 an «Alternative» component that no part instantiates is
  not generated (xslt/check/substitute.xsl checks it).
  Warnings: BND029 an inout port of a tool's profile, generated as an
  output and an input (bind/ports.xsl); BND004 a port left out, BND031 a
  connector left out with it (bind/ports.xsl, bind/connections.xsl);
  BND032 components given ports (bind/classes.xsl); BND034 ports typed by
  a library outside the model, said once (this file). Note BND033 a
  runtime port (bind/ports.xsl).
  BND028 the model draws no execution environment: its instances
  run in one default process per host (bind/instances.xsl), named once,
  on the first instance, with how to model the platform.
  Of the hardware platform (bind/devices.xsl): BND010 a Robot tag dof that
  is no non-negative integer; warnings BND021 a fixed-size array that does
  not fit the degrees of freedom of the Device its instance drives (DoF
  mismatch, seed 001), BND022 a driven Device that declares no degrees of
  freedom, BND023 a Device whose Robot tag dof, URDF chain and attribute
  dof disagree.
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

  <xsl:include href="../common/errors.xsl"/>
  <xsl:include href="../common/indent.xsl"/>
  <xsl:include href="../common/naming.xsl"/>
  <xsl:include href="../common/profile.xsl"/>
  <!-- values with units (period, memory, bandwidth) -->
  <xsl:include href="../common/units.xsl"/>
  <!-- inherited attributes and operations (fp:attributes, fp:operations) -->
  <xsl:include href="common/data-types.xsl"/>
  <!-- bind, by concern -->
  <xsl:include href="bind/values.xsl"/>
  <xsl:include href="bind/lookups.xsl"/>
  <xsl:include href="bind/instances.xsl"/>
  <xsl:include href="bind/ports.xsl"/>
  <xsl:include href="bind/connections.xsl"/>
  <xsl:include href="bind/sequence.xsl"/>
  <xsl:include href="bind/composites.xsl"/>
  <xsl:include href="bind/services.xsl"/>
  <xsl:include href="bind/devices.xsl"/>
  <xsl:include href="bind/runtime.xsl"/>
  <xsl:include href="bind/jobs.xsl"/>
  <xsl:include href="bind/classes.xsl"/>

  <xsl:output method="xml" indent="no" encoding="UTF-8"/>

  <xsl:mode on-no-match="shallow-copy"/>
  <xsl:mode name="m:bind" on-no-match="shallow-copy"/>
  <xsl:mode name="mp:bind-indented" on-no-match="fail"/>
  <xsl:mode name="mp:bind-document" on-no-match="fail"/>

  <xsl:key name="fp:id" match="*[@id]" use="@id"/>
  <xsl:key name="fp:part-by-type" match="pim:part" use="@type"/>
  <xsl:key name="fp:component-of-name" match="pim:component" use="string(@name)"/>
  <!-- a connector by the port of its own composite it ends on (an end without part) -->
  <xsl:key name="fp:connector-by-own-port" match="pim:connector" use="pim:end[not(@part)]/@role"/>
  <xsl:key name="fp:deployment-by-deployed" match="pim:deployment" use="tokenize(@deployed)"/>
  <xsl:key name="fp:manifestation-by-element" match="pim:manifestation" use="@element"/>
  <!-- the artifacts that manifest a part (component sets, bind/runtime.xsl) -->
  <xsl:key name="fp:manifests-part" match="pim:manifestation" use="if (key('fp:id', @element)/self::pim:part) then string(../@id) else ()"/>
  <!-- keys on the temporary trees of fp:binding ($work, $instance-tree, $bound-tree) -->
  <xsl:key name="fp:bc" match="pim:bound-component" use="@component"/>
  <xsl:key name="fp:ip-by-interface" match="fp:ip" use="@interface"/>
  <xsl:key name="fp:ip-by-end" match="fp:ip" use="@instance || '|' || @port"/>
  <xsl:key name="fp:instance-by-part" match="pim:instance" use="@xmi-id"/>
  <xsl:key name="fp:instance-by-component" match="pim:instance" use="@component"/>
  <!-- on the temporary tree of fp:sequence -->
  <xsl:key name="fp:edge-from" match="fp:edge" use="@from"/>
  <xsl:key name="fp:edge-to" match="fp:edge" use="@to"/>
  <xsl:key name="fp:placed" match="fp:placed" use="@position"/>


  <!-- ============================================================ entry -->
  <!-- The usual input (a pim:model with element-only content) is written
       in one pass: the model's children go straight through f:indent's
       rules (t:indented-content of common/indent.xsl), with the new binding
       last, which gives the bytes f:indent of the bound copy would give
       without building that copy of the whole model first; a child of the
       model that is indented already (f:indented: the application and the
       platform as import.xsl wrote them) is copied whole, which gives the
       same bytes with no template per node. Any other input takes the
       general way. -->
  <xsl:template match="/" as="document-node()">
    <!-- classes that are components (bind/classes.xsl) are bound as
         components: the model is bound with them written so -->
    <xsl:variable name="promoted" as="element(pim:class)*" select="pim:model ! fp:promoted-classes(.)"/>
    <xsl:variable name="portless" as="element()*" select="pim:model ! fp:portless-components(., $promoted)"/>
    <xsl:choose>
      <xsl:when test="exists($promoted) or exists($portless)">
        <xsl:apply-templates select="fp:with-classes-as-components(., $promoted, $portless)" mode="mp:bind-document"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:apply-templates select="." mode="mp:bind-document"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:template>

  <xsl:template match="/" mode="mp:bind-document" as="document-node()">
    <xsl:choose>
      <xsl:when test="pim:model[empty(text()[normalize-space()])]">
        <xsl:document>
          <xsl:for-each select="node()">
            <xsl:if test="position() gt 1">
              <xsl:text>&#10;</xsl:text>
            </xsl:if>
            <xsl:choose>
              <xsl:when test="self::pim:model">
                <xsl:apply-templates select="." mode="mp:bind-indented"/>
              </xsl:when>
              <xsl:otherwise>
                <xsl:apply-templates select="." mode="m:indent">
                  <xsl:with-param name="margin" select="'&#10;'"/>
                </xsl:apply-templates>
              </xsl:otherwise>
            </xsl:choose>
          </xsl:for-each>
        </xsl:document>
      </xsl:when>
      <xsl:otherwise>
        <xsl:variable name="result" as="document-node()">
          <xsl:document>
            <xsl:apply-templates select="node()" mode="m:bind"/>
          </xsl:document>
        </xsl:variable>
        <xsl:sequence select="f:indent($result)"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:template>

  <!-- the bound model, indented: what f:indent makes of the m:bind result
       below (one child per line, two spaces a level) -->
  <xsl:template match="pim:model" mode="mp:bind-indented" as="element(pim:model)">
    <xsl:sequence select="fp:check-references(.)"/>
    <xsl:variable name="binding" as="document-node()">
      <xsl:document>
        <xsl:call-template name="fp:binding"/>
      </xsl:document>
    </xsl:variable>
    <xsl:copy>
      <xsl:copy-of select="@*"/>
      <xsl:call-template name="t:indented-content">
        <xsl:with-param name="children" select="(* except pim:binding) | comment() | processing-instruction(), $binding/pim:binding"/>
        <xsl:with-param name="margin" select="'&#10;'"/>
        <!-- the model as import.xsl wrote it is indented already: copied
             whole, not a template per node -->
        <xsl:with-param name="reuse" select="true()"/>
      </xsl:call-template>
    </xsl:copy>
  </xsl:template>

  <xsl:template match="pim:model" mode="m:bind" as="element(pim:model)">
    <xsl:sequence select="fp:check-references(.)"/>
    <xsl:copy>
      <xsl:copy-of select="@*"/>
      <!-- no m:bind rule matches below pim:model: a deep copy, not a
           template dispatch per node -->
      <xsl:copy-of select="node() except pim:binding"/>
      <xsl:call-template name="fp:binding"/>
    </xsl:copy>
  </xsl:template>

  <!-- ============================================== reference checks -->
  <!-- every dangling reference of the model (BND001, BND002: a port's
       type, provided or required interface), all reported (f:fail-all);
       a reference to any element of the PIM is not dangling, whatever its
       kind (an element of the model the PIM holds no element for has no
       reference at all: xslt/import, @type-metaclass) -->
  <xsl:function name="fp:check-references" as="empty-sequence()">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:variable name="root" as="document-node()" select="root($model[1])"/>
    <xsl:variable name="problems" as="map(*)*">
      <xsl:for-each select="$model//pim:port">
        <xsl:variable name="port" as="element(pim:port)" select="."/>
        <xsl:for-each select="@type[not(key('fp:id', ., $root))],
                              (pim:provided, pim:required)/@interface[not(key('fp:id', ., $root)/self::pim:interface)]">
          <xsl:sequence select="map { 'code': 'BND002', 'id': string($port/@id), 'message':
              'port ''' || $port/@name || ''' refers to a missing interface ''' || . || '''' }"/>
        </xsl:for-each>
      </xsl:for-each>
      <xsl:for-each select="$model//pim:realization/@classifier, $model//pim:part/@type,
                            $model//pim:generalization/@general,
                            $model//pim:connector/pim:end/(@role | @part),
                            $model//pim:part/pim:value/@attribute,
                            $model//pim:manifestation/@element,
                            $model//pim:communication-path/pim:end/@node,
                            $model//(pim:provides | pim:requires)/@interface,
                            $model//pim:attribute/@type, $model//pim:parameter/@type">
        <xsl:if test="empty(key('fp:id', ., $root))">
          <xsl:sequence select="map { 'code': 'BND001', 'id': string((../ancestor-or-self::*[@id])[last()]/@id),
              'message': 'dangling reference ' || name(.) || '=''' || . || ''' on ' || local-name(..) }"/>
        </xsl:if>
      </xsl:for-each>
      <xsl:for-each select="$model//pim:connector/pim:end[@path]">
        <xsl:variable name="end" as="element()" select="."/>
        <xsl:for-each select="tokenize(@path)[empty(key('fp:id', ., $root))]">
          <xsl:sequence select="map { 'code': 'BND001', 'id': string($end/../@id), 'message':
              'dangling reference path=''' || . || ''' on end' }"/>
        </xsl:for-each>
      </xsl:for-each>
      <xsl:for-each select="$model//pim:deployment">
        <xsl:variable name="deployment" as="element(pim:deployment)" select="."/>
        <xsl:for-each select="tokenize(@deployed)[empty(key('fp:id', ., $root))]">
          <xsl:sequence select="map { 'code': 'BND001', 'id': string($deployment/@id), 'message':
              'dangling reference deployed=''' || . || ''' on deployment ''' || $deployment/@name || '''' }"/>
        </xsl:for-each>
      </xsl:for-each>
    </xsl:variable>
    <xsl:sequence select="f:fail-all($problems)"/>
  </xsl:function>

  <!-- ========================================================= binding -->
  <xsl:template name="fp:binding" as="element(pim:binding)">
    <xsl:context-item as="element(pim:model)" use="required"/>
    <xsl:variable name="root" as="document-node()" select="root(.)"/>
    <xsl:variable name="components" as="element(pim:component)*" select="pim:application//pim:component"/>
    <xsl:variable name="all-tops" as="element(pim:component)*"
        select="$components[fp:is-composite(.)][empty(key('fp:part-by-type', @id, $root))]"/>
    <!-- the top the model names (a UML-RT top capsule), when it is one -->
    <xsl:variable name="tops" as="element(pim:component)*"
        select="if ($all-tops[@name = current()/pim:application/@top]) then $all-tops[@name = current()/pim:application/@top]
                else $all-tops"/>
    <!-- the processes: threads (bind/runtime.xsl) are parts of them -->
    <xsl:variable name="ees" as="element(pim:node)*" select="fp:execution-environments($root)[not(fp:is-thread(.))]"/>
    <xsl:variable name="hosts" as="element(pim:node)*" select="fp:hosts($root)"/>
    <!-- a composite inside itself would make the walk endless: refused first -->
    <xsl:sequence select="f:fail-all(fp:composition-cycles($components))"/>
    <!-- the parts of the top composites, any depth (bind/composites.xsl) -->
    <xsl:variable name="expansion" as="document-node()" select="fp:expansion($tops)"/>
    <!-- instances and bound components live in documents of their own, so
         that keys find them (temporary trees, copied to the result) -->
    <xsl:sequence select="f:fail-all((fp:thread-problems($root), fp:deployment-problems($expansion, $components, $ees)))"/>
    <xsl:variable name="instance-tree" as="document-node()" select="fp:instance-tree($expansion, $components, $ees, $hosts)"/>
    <!-- an error of one instance (a bad value: BND010, BND006 ...) does not
         hide those of the others: each was caught, all are raised here -->
    <xsl:sequence select="f:fail-all($instance-tree/fp:error ! f:error-map(@description))"/>
    <xsl:variable name="instances" as="element(pim:instance)*" select="$instance-tree/pim:instance"/>
    <xsl:sequence select="fp:warn-default-processes(., $instances)"/>
    <!-- an «Alternative» that no part instantiates: said, not dropped in silence -->
    <xsl:for-each select="$components[exists(f:stereotype(., 'Alternative'))][empty(key('fp:instance-by-component', @id, $instance-tree))]">
      <xsl:message select="'SUB030: component ''' || @name || ''' is an «Alternative» of '''
          || string-join(f:stereotype(., 'Alternative')/pim:tag[@name eq 'replaces'] ! string((key('fp:id', @value, $root)/@name, @value)[1]), ''', ''')
          || ''': no instance of the system, so nothing is generated for it; robomda check checks the swap'
          || ' [xmi:id=' || @id || ']'"/>
    </xsl:for-each>
    <xsl:variable name="same-names" as="map(*)*">
      <xsl:for-each-group select="$instances" group-by="@name">
        <xsl:if test="count(current-group()) gt 1">
          <xsl:sequence select="map { 'code': 'BND009', 'id': string(current-group()[2]/@xmi-id),
              'message': 'two instances are named ''' || current-grouping-key() || ''''
              || fp:paths-text(current-group(), $root) }"/>
        </xsl:if>
      </xsl:for-each-group>
    </xsl:variable>
    <xsl:sequence select="f:fail-all($same-names)"/>
    <!-- every port problem of every instantiated component at once -->
    <xsl:sequence select="f:fail-all($components[exists(key('fp:instance-by-component', @id, $instance-tree))]
                          ! (let $c := ., $r := fp:realizing-class(.) return $c/pim:port ! fp:port-problems(., $c, $r)))"/>
    <xsl:sequence select="f:fail-all(fp:composite-problems($tops | key('fp:id', $expansion/fp:composite/@component, $root)))"/>
    <xsl:variable name="bound-tree" as="document-node()" select="fp:bound-tree($components, $instance-tree)"/>
    <!-- ports typed by a type of a library robomda does not have (RobotML's
         platform library, a tool's pathmap:// library): left out, said once -->
    <xsl:variable name="unknown-typed" as="element(pim:port)*"
        select="$components[exists(key('fp:instance-by-component', @id, $instance-tree))]/pim:port
                [not(@runtime)][not(@type-library = ('local', 'ros-message'))][empty(@type)][empty(@primitive)]
                [not(pim:provided or pim:required)]"/>
    <xsl:if test="exists($unknown-typed)">
      <xsl:sequence select="f:warn('BND034', string($unknown-typed[1]/@id), count($unknown-typed) || ' port'
          || (if (count($unknown-typed) gt 1) then 's are' else ' is') || ' typed by a data type of a library outside the model,'
          || ' which robomda does not have (' || string-join(($unknown-typed ! ('''' || @name || ''' of ' || ../@name || ': '
          || @type-name))[position() le 5], ', ') || (if (count($unknown-typed) gt 5) then ' ...' else '')
          || '): they carry no data robomda can generate and are left out, with their connectors; give them data types'
          || ' of the model (or copy the library''s types into it)')"/>
    </xsl:if>
    <xsl:sequence select="f:fail-all($bound-tree/fp:error ! f:error-map(@description))"/>
    <xsl:variable name="bound" as="element(pim:bound-component)*" select="$bound-tree/pim:bound-component"/>
    <xsl:sequence select="f:fail-all(fp:conformance-problems($root, $bound))"/>
    <!-- working tree: one fp:ip per instance data port -->
    <xsl:variable name="work" as="document-node()" select="fp:work($instances, $bound-tree)"/>
    <xsl:variable name="uses" as="element(fp:use)*" select="fp:connector-uses($tops, $expansion)"/>
    <!-- the writer -> reader pairs and the calls each connector makes -->
    <!-- in one tree of their own: in document order as made, so that the
         steps below need not sort a sequence of parentless elements -->
    <xsl:variable name="resolved-tree" as="document-node()">
      <xsl:document><xsl:sequence select="fp:connector-pairs($root, $uses, $work)"/></xsl:document>
    </xsl:variable>
    <xsl:variable name="resolved" as="element()*" select="$resolved-tree/*"/>
    <xsl:variable name="raw-connections" as="element(pim:connection)*"
        select="if (exists($uses)) then fp:connections-from-connectors($root, $uses, $resolved)
                else fp:connections-from-interfaces(., $work)"/>
    <xsl:variable name="calls" as="element(pim:call)*"
        select="if (exists($uses)) then fp:calls-from-pairs($root, $resolved/self::fp:call-pair)
                else fp:calls-from-interfaces($root, $work)"/>
    <xsl:sequence select="fp:check-devices($root), fp:warn-dof($root, $instances, $bound, $raw-connections)"/>
    <xsl:variable name="processes" as="element(pim:process)*" select="fp:processes(., $instances, $hosts)"/>
    <xsl:sequence select="f:fail-all(fp:process-problems($root, $processes))"/>
    <xsl:variable name="sequenced" as="document-node()">
      <xsl:document><xsl:sequence select="fp:sequence(., $instances, $instance-tree)"/></xsl:document>
    </xsl:variable>
    <!-- jobs and subsystems (bind/jobs.xsl, docs/jobs.md) -->
    <xsl:sequence select="f:fail-all(fp:job-problems(., $sequenced))"/>
    <pim:binding instances-from="{if (exists($tops)) then 'parts' else 'components'}"
                 connections-from="{if (exists($uses)) then 'connectors' else 'interfaces'}">
      <xsl:sequence select="$hosts ! fp:host(., count($hosts))"/>
      <xsl:sequence select="fp:default-host(.)[@xmi-id = $instances/@host]"/>
      <xsl:sequence select="fp:links(., $hosts), $processes, fp:component-sets(., $hosts)"/>
      <xsl:sequence select="fp:libraries(.)"/>
      <xsl:sequence select="$bound, $instance-tree/pim:composite-instance, fp:with-initial-values(., $sequenced/pim:instance)"/>
      <xsl:sequence select="fp:uniquely-named($raw-connections), fp:uniquely-named($calls)"/>
      <xsl:sequence select="fp:bound-jobs(., $sequenced)"/>
    </pim:binding>
  </xsl:template>

  <!-- BND028 once, on the first instance, when the instances run in
       default processes (the model draws no execution environment) -->
  <xsl:function name="fp:warn-default-processes" as="empty-sequence()">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:variable name="undrawn" as="element(pim:instance)*" select="$instances[empty(@middleware)]"/>
    <xsl:variable name="hosts" as="xs:string*"
        select="distinct-values($undrawn/@host) ! (if (. eq $model/@id) then 'localhost (127.0.0.1)'
                                                   else '''' || key('fp:id', ., root($model))/@name || '''')"/>
    <xsl:if test="exists($undrawn)">
      <xsl:sequence select="f:warn('BND028', string($undrawn[1]/@xmi-id), 'the model draws no execution environment: its '
          || count($undrawn) || ' component instance' || (if (count($undrawn) gt 1) then 's' else '') || ' ('''
          || string-join($undrawn/@name, ''', ''') || ''') run in one default process on host ' || string-join($hosts, ', host ')
          || ', on the middleware of the target generated; to model the platform, draw a Node (the host) with an'
          || ' ExecutionEnvironment (a process: its «Middleware» kind, else its name, is the middleware) and a'
          || ' Deployment of each part on it, or nest the components, or artifacts that manifest them, in the'
          || ' ExecutionEnvironment (docs/profile.md, docs/deployment.md)')"/>
    </xsl:if>
  </xsl:function>

  <!-- $elements with their @name made unique among them (f:unique-names) -->
  <xsl:function name="fp:uniquely-named" as="element()*">
    <xsl:param name="elements" as="element()*"/>
    <xsl:variable name="names" as="xs:string*" select="f:unique-names($elements/@name)"/>
    <xsl:for-each select="$elements">
      <xsl:variable name="position" as="xs:integer" select="position()"/>
      <xsl:copy>
        <xsl:attribute name="name" select="$names[$position]"/>
        <xsl:sequence select="@* except @name, node()"/>
      </xsl:copy>
    </xsl:for-each>
  </xsl:function>

  <!-- " (parts a.b and a_b) ...": the paths of same-named nested instances -->
  <xsl:function name="fp:paths-text" as="xs:string">
    <xsl:param name="instances" as="element(pim:instance)+"/>
    <xsl:param name="root" as="document-node()"/>
    <xsl:variable name="tops" as="xs:string*" select="distinct-values($instances/@composite)"/>
    <xsl:sequence select="if (count($tops) gt 1)
        then ' (parts of ' || string-join($tops ! ('''' || key('fp:id', ., $root)/@name || ''''), ' and ')
             || ': the model draws several systems, composites no part uses, and robomda generates their parts as one'
             || ' system: draw one composite whose parts they are, or keep one system in the model)'
        else if (empty($instances/@path)) then ''
        else ' (parts ' || string-join($instances ! string((@path, @name)[1]), ' and ')
             || '): rename a part so that the names differ with the dots made underscores'"/>
  </xsl:function>

  <!-- every instance without an execution environment (BND006) and every
       environment of an unknown middleware (BND003), as maps for
       f:fail-all: all of them at once -->
  <xsl:function name="fp:deployment-problems" as="map(*)*">
    <xsl:param name="expansion" as="document-node()"/>
    <xsl:param name="components" as="element(pim:component)*"/>
    <xsl:param name="ees" as="element(pim:node)*"/>
    <!-- the part (if any), component and enclosing elements of each instance -->
    <xsl:variable name="placed" as="map(*)*"
        select="if (exists($expansion/fp:unit))
                then $expansion/fp:unit ! (let $root := root($components[1]) return
                     map { 'part': key('fp:id', @part, $root), 'component': key('fp:id', @component, $root),
                           'around': tokenize(@around) })
                else $components[not(@abstract = ('true', '1'))][pim:port or pim:realization][empty(f:stereotype(., 'Alternative'))]
                     ! map { 'component': ., 'around': () }"/>
    <xsl:variable name="found" as="element(pim:node)*"
        select="$placed ! fp:instance-ee(?part, ?component, ?around, $ees)"/>
    <!-- a model that draws no execution environment runs its instances in
         default processes (BND028, fp:warn-default-processes) -->
    <xsl:sequence select="$placed[not(fp:draws-no-process(root($components[1])))]
                                 [empty(fp:instance-ee(?part, ?component, ?around, $ees))]
                            ! fp:no-ee-problem(?part, ?component, $ees),
                          ($found ! fp:process-of(.))/. ! fp:middleware-problems(.)"/>
  </xsl:function>

  <!-- the instances, in a document of their own (keys find them there):
       the units of the expansion (after a pim:composite-instance per
       composite part), else one per component with ports or a
       realization; an instance that fails is an fp:error element -->
  <xsl:function name="fp:instance-tree" as="document-node()">
    <xsl:param name="expansion" as="document-node()"/>
    <xsl:param name="components" as="element(pim:component)*"/>
    <xsl:param name="ees" as="element(pim:node)*"/>
    <xsl:param name="hosts" as="element(pim:node)*"/>
    <xsl:document>
      <xsl:choose>
        <xsl:when test="exists($expansion/fp:unit)">
          <xsl:variable name="root" as="document-node()" select="root($components[1])"/>
          <xsl:for-each select="$expansion/fp:composite">
            <pim:composite-instance name="{@name}" path="{@path}" xmi-id="{@part}" component="{@component}">
              <xsl:sequence select="@parent"/>
            </pim:composite-instance>
          </xsl:for-each>
          <xsl:for-each select="$expansion/fp:unit">
            <xsl:try>
              <xsl:sequence select="fp:instance(key('fp:id', @part, $root), key('fp:id', @component, $root), ., $ees, $hosts, ())"/>
              <xsl:catch><xsl:sequence select="fp:caught($err:code, $err:description, $err:value)"/></xsl:catch>
            </xsl:try>
          </xsl:for-each>
        </xsl:when>
        <xsl:otherwise>
          <xsl:variable name="instantiated" as="element(pim:component)*"
              select="$components[not(@abstract = ('true', '1'))][pim:port or pim:realization][empty(f:stereotype(., 'Alternative'))]"/>
          <xsl:for-each select="$instantiated">
            <xsl:try>
              <xsl:sequence select="fp:instance((), ., (), $ees, $hosts, fp:component-name(.)[. ne current()/@name])"/>
              <xsl:catch><xsl:sequence select="fp:caught($err:code, $err:description, $err:value)"/></xsl:catch>
            </xsl:try>
          </xsl:for-each>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:document>
  </xsl:function>

  <!-- the bound components of the instantiated components, in a document
       of their own; a component that fails is an fp:error element -->
  <xsl:function name="fp:bound-tree" as="document-node()">
    <xsl:param name="components" as="element(pim:component)*"/>
    <xsl:param name="instance-tree" as="document-node()"/>
    <xsl:document>
      <xsl:for-each select="$components[exists(key('fp:instance-by-component', @id, $instance-tree))]">
        <xsl:try>
          <xsl:sequence select="fp:bound-component(.)"/>
          <xsl:catch><xsl:sequence select="fp:caught($err:code, $err:description, $err:value)"/></xsl:catch>
        </xsl:try>
      </xsl:for-each>
    </xsl:document>
  </xsl:function>

  <!-- the working tree of the connections: one fp:ip per data port of an instance -->
  <xsl:function name="fp:work" as="document-node()">
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="bound-tree" as="document-node()"/>
    <xsl:document>
      <fp:work>
        <xsl:for-each select="$instances">
          <xsl:variable name="inst" as="element(pim:instance)" select="."/>
          <xsl:for-each select="key('fp:bc', $inst/@component, $bound-tree)/pim:data-port">
            <fp:ip instance="{$inst/@name}" port="{@port}" data-port="{@name}"
                   direction="{@direction}" interface="{@interface}"
                   type-key="{(@primitive, @type)[1]}{fp:multiplicity-label(.)}">
              <!-- a message of a UML-RT message set: matched by the message -->
              <xsl:if test="fp:is-message-set(key('fp:id', @interface, root($inst)))">
                <xsl:attribute name="message" select="@datum"/>
              </xsl:if>
            </fp:ip>
          </xsl:for-each>
          <!-- a service port: out where provided, in where required -->
          <xsl:for-each select="key('fp:bc', $inst/@component, $bound-tree)/pim:service-port">
            <fp:ip instance="{$inst/@name}" port="{@port}" data-port="{@name}" kind="service"
                   direction="{if (@role eq 'provided') then 'out' else 'in'}" interface="{@interface}"/>
          </xsl:for-each>
        </xsl:for-each>
      </fp:work>
    </xsl:document>
  </xsl:function>

  <!-- an error xsl:catch caught: ours (f:fail: a finding about the model)
       as an fp:error element to raise with the others; anything else
       (a bug) raised again as it was. No errors="re:*" on xsl:catch:
       SaxonJS takes only QNames there -->
  <xsl:function name="fp:caught" as="element(fp:error)">
    <xsl:param name="code" as="xs:QName"/>
    <xsl:param name="description" as="xs:string?"/>
    <xsl:param name="value" as="item()*"/>
    <xsl:sequence select="if (namespace-uri-from-QName($code) eq 'urn:robomda:error')
                          then fp:error-element($description) else error($code, string($description), $value)"/>
  </xsl:function>

  <xsl:function name="fp:error-element" as="element(fp:error)">
    <xsl:param name="description" as="xs:string?"/>
    <fp:error description="{$description}"/>
  </xsl:function>

</xsl:stylesheet>
