<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/10-bind.xsl - resolve the platform binding of a PIM.

  Reads:   a PIM, urn:robomda:pim:1 (schemas/pim/1/pim.xsd), as written by
           xslt/import/import.xsl; an existing pim:binding is replaced.
  Writes:  the same PIM with pim:binding appended (schemas/pim/1/binding.xsd),
           indented as f:indent (common/indent.xsl) indents it; a model with
           element-only content is indented in the same pass, through
           f:indent's own rules (t:indented-content), with no copy of it first.
  Params:  none.

  What it resolves (docs/profile.md: stereotypes of profile "robomda" first,
  else the unprofiled conventions of seed 000, else defaults):
  - instances: when a composite component has parts typed by components and
    is not itself the type of a part ("top composite"), the parts of all top
    composites are the instances and their assembly connectors the
    connections; otherwise one instance per non-abstract component that has
    ports or a realization, named after the component. Instance names are
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
  BND009 and every port problem (BND002, BND004, BND005) of the
  instantiated components at once, with f:fail-all):
    BND001  dangling reference: an id attribute points to no PIM element
    BND002  a port is typed by, provides or requires a missing interface
    BND003  unknown middleware name (names the ExecutionEnvironment); a
            Middleware stereotype without kind means the profile default
            (xslt/import/profile-defaults.xml: OROCOS)
    BND004  an interface used by a port carries no datum (no attribute)
    BND005  an interface used by a port carries several data (attributes)
    BND006  an instance is deployed to no execution environment and the model
            has none or several
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

  <xsl:output method="xml" indent="no" encoding="UTF-8"/>

  <xsl:mode on-no-match="shallow-copy"/>
  <xsl:mode name="m:bind" on-no-match="shallow-copy"/>
  <xsl:mode name="mp:bind-indented" on-no-match="fail"/>

  <xsl:key name="fp:id" match="*[@id]" use="@id"/>
  <xsl:key name="fp:part-by-type" match="pim:part" use="@type"/>
  <xsl:key name="fp:deployment-by-deployed" match="pim:deployment" use="tokenize(@deployed)"/>
  <xsl:key name="fp:manifestation-by-element" match="pim:manifestation" use="@element"/>
  <!-- keys on the temporary trees of fp:binding ($work, $instance-tree, $bound-tree) -->
  <xsl:key name="fp:bc" match="pim:bound-component" use="@component"/>
  <xsl:key name="fp:ip-by-interface" match="fp:ip" use="@interface"/>
  <xsl:key name="fp:ip-by-end" match="fp:ip" use="@part || '|' || @port"/>
  <xsl:key name="fp:instance-by-part" match="pim:instance" use="@xmi-id"/>
  <xsl:key name="fp:instance-by-name" match="pim:instance" use="@name"/>
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
       without building that copy of the whole model first. Any other input
       takes the general way. -->
  <xsl:template match="/" as="document-node()">
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
                            $model//pim:manifestation/@element,
                            $model//pim:communication-path/pim:end/@node,
                            $model//(pim:provides | pim:requires)/@interface,
                            $model//pim:attribute/@type, $model//pim:parameter/@type">
        <xsl:if test="empty(key('fp:id', ., $root))">
          <xsl:sequence select="map { 'code': 'BND001', 'id': string((../ancestor-or-self::*[@id])[last()]/@id),
              'message': 'dangling reference ' || name(.) || '=''' || . || ''' on ' || local-name(..) }"/>
        </xsl:if>
      </xsl:for-each>
      <xsl:for-each select="$model//pim:deployment">
        <xsl:variable name="d" as="element(pim:deployment)" select="."/>
        <xsl:for-each select="tokenize(@deployed)[empty(key('fp:id', ., $root))]">
          <xsl:sequence select="map { 'code': 'BND001', 'id': string($d/@id), 'message':
              'dangling reference deployed=''' || . || ''' on deployment ''' || $d/@name || '''' }"/>
        </xsl:for-each>
      </xsl:for-each>
    </xsl:variable>
    <xsl:sequence select="f:fail-all($problems)"/>
  </xsl:function>

  <!-- ===================================================== stereotypes -->
  <!-- a tag value of stereotype $stereo on $e; enumeration literals given by
       reference resolve to their name; "Kind::LIT" / "Kind.LIT" -> "LIT" -->
  <xsl:function name="fp:tag" as="xs:string?">
    <xsl:param name="e" as="element()?"/>
    <xsl:param name="stereo" as="xs:string"/>
    <xsl:param name="tag" as="xs:string"/>
    <xsl:variable name="t" as="element()?" select="f:stereotype($e, $stereo)/pim:tag[@name eq $tag][1]"/>
    <xsl:sequence select="if (empty($t)) then ()
        else if ($t/@ref = ('true', '1')) then string(key('fp:id', $t/@value, root($t))/@name)
        else string($t/@value)"/>
  </xsl:function>

  <xsl:function name="fp:literal" as="xs:string">
    <xsl:param name="v" as="xs:string"/>
    <xsl:sequence select="if (contains($v, ':') or contains($v, '.'))
                          then replace(normalize-space($v), '^.*(::|\.)([A-Za-z_][A-Za-z0-9_]*)$', '$2')
                          else normalize-space($v)"/>
  </xsl:function>

  <!-- first tag value found on the elements $es, with its source -->
  <xsl:function name="fp:first-tag" as="xs:string*">
    <xsl:param name="es" as="element()*"/>
    <xsl:param name="stereo" as="xs:string"/>
    <xsl:param name="tag" as="xs:string"/>
    <xsl:sequence select="(for $e in $es return fp:tag($e, $stereo, $tag))[normalize-space(.)][1]"/>
  </xsl:function>

  <!-- default value of the convention attribute $name of $e -->
  <xsl:function name="fp:conv" as="xs:string?">
    <xsl:param name="e" as="element()?"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:sequence select="$e/pim:attribute[@name eq $name][@default][1]/@default ! string(.)"/>
  </xsl:function>

  <!-- the id of the attribute holding that default value -->
  <xsl:function name="fp:conv-holder" as="xs:string">
    <xsl:param name="e" as="element()?"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:sequence select="string($e/pim:attribute[@name eq $name][@default][1]/@id)"/>
  </xsl:function>

  <!-- ================================================= value parsing -->
  <xsl:function name="fp:strip" as="xs:string">
    <xsl:param name="v" as="xs:string"/>
    <xsl:sequence select="if (contains($v, '&quot;') or contains($v, ''''))
                          then replace(normalize-space($v), '^[&quot;'']|[&quot;'']$', '')
                          else normalize-space($v)"/>
  </xsl:function>

  <xsl:function name="fp:number" as="xs:double">
    <xsl:param name="v" as="xs:string"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:variable name="s" as="xs:string" select="replace(fp:strip($v), '[fFdD]$', '')"/>
    <xsl:sequence select="if ($s castable as xs:double and number($s) ge 0) then number($s)
        else f:fail('BND010', $id, $what || ': ''' || $v || ''' is not a non-negative number')"/>
  </xsl:function>

  <xsl:function name="fp:integer" as="xs:integer">
    <xsl:param name="v" as="xs:string"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:variable name="d" as="xs:double" select="fp:number($v, $what, $id)"/>
    <xsl:sequence select="if ($d eq floor($d)) then xs:integer($d)
        else f:fail('BND010', $id, $what || ': ''' || $v || ''' is not an integer')"/>
  </xsl:function>

  <xsl:function name="fp:boolean" as="xs:boolean">
    <xsl:param name="v" as="xs:string"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:variable name="s" as="xs:string" select="lower-case(fp:strip($v))"/>
    <xsl:sequence select="if ($s = ('true', '1', 'yes')) then true()
        else if ($s = ('false', '0', 'no')) then false()
        else f:fail('BND010', $id, $what || ': ''' || $v || ''' is not a boolean')"/>
  </xsl:function>

  <xsl:function name="fp:enum" as="xs:string">
    <xsl:param name="v" as="xs:string"/>
    <xsl:param name="allowed" as="xs:string+"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:variable name="s" as="xs:string"
        select="upper-case(replace(fp:literal(fp:strip($v)), '[\s\-]', '_'))"/>
    <xsl:variable name="hit" as="xs:string?"
        select="$allowed[translate(., '_', '') eq translate($s, '_', '')][1]"/>
    <xsl:sequence select="if (exists($hit)) then $hit
        else f:fail('BND010', $id, $what || ': ''' || $v || ''' is not one of '
                    || string-join($allowed, ', '))"/>
  </xsl:function>

  <!-- ================================================ model look-ups -->
  <xsl:function name="fp:realizing-class" as="element(pim:class)?">
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:variable name="root" as="document-node()" select="root($c[1])"/>
    <xsl:sequence select="(for $r in $c/pim:realization
                           return key('fp:id', $r/@classifier, $root)/self::pim:class)[1]"/>
  </xsl:function>

  <xsl:function name="fp:execution-environments" as="element(pim:node)*">
    <xsl:param name="root" as="document-node()"/>
    <xsl:sequence select="$root/pim:model/pim:platform//pim:node[@kind eq 'execution-environment']"/>
  </xsl:function>

  <xsl:function name="fp:hosts" as="element(pim:node)*">
    <xsl:param name="root" as="document-node()"/>
    <xsl:sequence select="$root/pim:model/pim:platform//pim:node
                [@kind eq 'node' or exists(f:stereotype(., 'Host'))]"/>
  </xsl:function>

  <!-- the default values of the robomda profile's tags (what a tool that
       leaves out a tag equal to its default means; the import drops such
       tags too, so that every tool gives the same PIM) -->
  <xsl:variable name="fp:profile-defaults" as="document-node()" select="doc('../import/profile-defaults.xml')"/>

  <xsl:function name="fp:tag-default" as="xs:string?">
    <xsl:param name="stereo" as="xs:string"/>
    <xsl:param name="tag" as="xs:string"/>
    <xsl:sequence select="$fp:profile-defaults/*/*/*[@stereotype eq $stereo][@name eq $tag][1]/@default/string()"/>
  </xsl:function>

  <!-- what names the middleware of an execution environment: its Middleware
       kind; a Middleware stereotype that leaves kind out means the profile
       default (OROCOS); without the stereotype, the environment's name -->
  <xsl:function name="fp:middleware-name" as="xs:string">
    <xsl:param name="ee" as="element(pim:node)"/>
    <xsl:variable name="tag" as="xs:string?"
        select="(fp:tag($ee, 'Middleware', 'kind')[normalize-space(.)],
                 if (exists(f:stereotype($ee, 'Middleware'))) then fp:tag-default('Middleware', 'kind') else ())[1]"/>
    <xsl:sequence select="if (normalize-space($tag)) then fp:literal($tag) else string($ee/@name)"/>
  </xsl:function>

  <!-- the middleware fp:middleware-name means, () when it is unknown -->
  <xsl:function name="fp:known-middleware" as="xs:string?">
    <xsl:param name="ee" as="element(pim:node)"/>
    <xsl:variable name="key" as="xs:string" select="upper-case(replace(fp:middleware-name($ee), '[^A-Za-z0-9]', ''))"/>
    <xsl:sequence select="
        if ($key = ('OROCOS', 'OROCOSRTT', 'RTT', 'OROCOSRTT2')) then 'OROCOS'
        else if ($key = ('ROS', 'ROS1')) then 'ROS'
        else if ($key eq 'ROS2') then 'ROS2'
        else if ($key = ('OPENRTM', 'OPENRTMAIST')) then 'OpenRTM'
        else ()"/>
  </xsl:function>

  <!-- the middleware of an execution environment; BND003 when unknown -->
  <xsl:function name="fp:middleware" as="xs:string">
    <xsl:param name="ee" as="element(pim:node)"/>
    <xsl:sequence select="(fp:known-middleware($ee), f:fail-all(fp:middleware-problems($ee)))[1]"/>
  </xsl:function>

  <!-- BND003 about $ee, if its middleware is unknown (fp:middleware) -->
  <xsl:function name="fp:middleware-problems" as="map(*)?">
    <xsl:param name="ee" as="element(pim:node)"/>
    <xsl:sequence select="if (exists(fp:known-middleware($ee))) then () else
        map { 'code': 'BND003', 'id': string($ee/@id), 'message': 'unknown middleware ''' || fp:middleware-name($ee)
              || ''' of execution environment ''' || $ee/@name || ''' (expected OROCOS, ROS, ROS2 or OpenRTM)' }"/>
  </xsl:function>

  <!-- ========================================================= binding -->
  <xsl:template name="fp:binding" as="element(pim:binding)">
    <xsl:context-item as="element(pim:model)" use="required"/>
    <xsl:variable name="root" as="document-node()" select="root(.)"/>
    <xsl:variable name="components" as="element(pim:component)*" select="pim:application//pim:component"/>
    <xsl:variable name="tops" as="element(pim:component)*"
        select="$components[pim:part[key('fp:id', @type, $root)/self::pim:component]]
                           [empty(key('fp:part-by-type', @id, $root))]"/>
    <xsl:variable name="ees" as="element(pim:node)*" select="fp:execution-environments($root)"/>
    <xsl:variable name="hosts" as="element(pim:node)*" select="fp:hosts($root)"/>
    <!-- instances and bound components live in documents of their own, so
         that keys find them (temporary trees, copied to the result) -->
    <!-- every instance without an execution environment (BND006) and
         every environment of an unknown middleware (BND003) at once -->
    <xsl:variable name="instance-ees" as="element(pim:node)*">
      <xsl:choose>
        <xsl:when test="exists($tops)">
          <xsl:for-each select="$tops/pim:part[key('fp:id', @type, $root)/self::pim:component]">
            <xsl:sequence select="fp:instance-ee(., key('fp:id', @type, $root), .., $ees)"/>
          </xsl:for-each>
        </xsl:when>
        <xsl:otherwise>
          <xsl:for-each select="$components[not(@abstract = ('true', '1'))][pim:port or pim:realization]">
            <xsl:sequence select="fp:instance-ee((), ., (), $ees)"/>
          </xsl:for-each>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:variable>
    <xsl:sequence select="f:fail-all((
        if (exists($tops)) then $tops/pim:part[key('fp:id', @type, $root)/self::pim:component]
                                  [empty(fp:instance-ee(., key('fp:id', @type, $root), .., $ees))]
                                ! fp:no-ee-problem(., key('fp:id', @type, $root), $ees)
        else $components[not(@abstract = ('true', '1'))][pim:port or pim:realization]
                        [empty(fp:instance-ee((), ., (), $ees))] ! fp:no-ee-problem((), ., $ees),
        ($instance-ees/.) ! fp:middleware-problems(.)))"/>
    <xsl:variable name="instance-tree" as="document-node()">
      <xsl:document>
        <xsl:choose>
          <xsl:when test="exists($tops)">
            <xsl:for-each select="$tops/pim:part[key('fp:id', @type, $root)/self::pim:component]">
              <xsl:try>
                <xsl:sequence select="fp:instance(., key('fp:id', @type, $root), .., $ees, $hosts)"/>
                <xsl:catch><xsl:sequence select="fp:caught($err:code, $err:description, $err:value)"/></xsl:catch>
              </xsl:try>
            </xsl:for-each>
          </xsl:when>
          <xsl:otherwise>
            <xsl:for-each select="$components[not(@abstract = ('true', '1'))][pim:port or pim:realization]">
              <xsl:try>
                <xsl:sequence select="fp:instance((), ., (), $ees, $hosts)"/>
                <xsl:catch><xsl:sequence select="fp:caught($err:code, $err:description, $err:value)"/></xsl:catch>
              </xsl:try>
            </xsl:for-each>
          </xsl:otherwise>
        </xsl:choose>
      </xsl:document>
    </xsl:variable>
    <!-- an error of one instance (a bad value: BND010, BND006 ...) does not
         hide those of the others: each was caught, all are raised here -->
    <xsl:sequence select="f:fail-all($instance-tree/fp:error ! f:error-map(@description))"/>
    <xsl:variable name="instances" as="element(pim:instance)*" select="$instance-tree/pim:instance"/>
    <xsl:variable name="same-names" as="map(*)*">
      <xsl:for-each-group select="$instances" group-by="@name">
        <xsl:if test="count(current-group()) gt 1">
          <xsl:sequence select="map { 'code': 'BND009', 'id': string(current-group()[2]/@xmi-id),
              'message': 'two instances are named ''' || current-grouping-key() || '''' }"/>
        </xsl:if>
      </xsl:for-each-group>
    </xsl:variable>
    <xsl:sequence select="f:fail-all($same-names)"/>
    <!-- every port problem of every instantiated component at once -->
    <xsl:sequence select="f:fail-all($components[exists(key('fp:instance-by-component', @id, $instance-tree))]
                          ! (let $c := ., $r := fp:realizing-class(.) return $c/pim:port ! fp:port-problems(., $c, $r)))"/>
    <xsl:variable name="bound-tree" as="document-node()">
      <xsl:document>
        <xsl:for-each select="$components[exists(key('fp:instance-by-component', @id, $instance-tree))]">
          <xsl:try>
            <xsl:sequence select="fp:bound-component(.)"/>
            <xsl:catch><xsl:sequence select="fp:caught($err:code, $err:description, $err:value)"/></xsl:catch>
          </xsl:try>
        </xsl:for-each>
      </xsl:document>
    </xsl:variable>
    <xsl:sequence select="f:fail-all($bound-tree/fp:error ! f:error-map(@description))"/>
    <xsl:variable name="bound" as="element(pim:bound-component)*" select="$bound-tree/pim:bound-component"/>
    <!-- working tree: one fp:ip per instance data port -->
    <xsl:variable name="work" as="document-node()">
      <xsl:document>
        <fp:work>
          <xsl:for-each select="$instances">
            <xsl:variable name="inst" as="element(pim:instance)" select="."/>
            <xsl:for-each select="key('fp:bc', $inst/@component, $bound-tree)/pim:data-port">
              <fp:ip instance="{$inst/@name}" part="{$inst/@xmi-id}" port="{@port}" data-port="{@name}"
                     direction="{@direction}" interface="{@interface}"
                     type-key="{(@primitive, @type)[1]}"/>
            </xsl:for-each>
          </xsl:for-each>
        </fp:work>
      </xsl:document>
    </xsl:variable>
    <xsl:variable name="connectors" as="element(pim:connector)*"
        select="$tops/pim:connector[not(@kind eq 'delegation')][count(pim:end[@part]) ge 2]"/>
    <xsl:variable name="raw-connections" as="element(pim:connection)*"
        select="if (exists($connectors)) then fp:connections-from-connectors($connectors, $work)
                else fp:connections-from-interfaces(., $work)"/>
    <xsl:variable name="names" as="xs:string*" select="f:unique-names($raw-connections/@name)"/>
    <pim:binding instances-from="{if (exists($tops)) then 'parts' else 'components'}"
                 connections-from="{if (exists($connectors)) then 'connectors' else 'interfaces'}">
      <xsl:sequence select="$hosts ! fp:host(., count($hosts))"/>
      <xsl:sequence select="fp:libraries(.)"/>
      <xsl:sequence select="$bound, fp:sequence(., $instances, $instance-tree)"/>
      <xsl:for-each select="$raw-connections">
        <xsl:variable name="i" as="xs:integer" select="position()"/>
        <xsl:copy>
          <xsl:attribute name="name" select="$names[$i]"/>
          <xsl:sequence select="@* except @name, node()"/>
        </xsl:copy>
      </xsl:for-each>
    </pim:binding>
  </xsl:template>

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

  <!-- ============================================ deployment sequence -->
  <!-- the deployment-sequence dependencies of the model -->
  <xsl:function name="fp:start-after-dependencies" as="element(pim:dependency)*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:sequence select="$model/pim:application//pim:dependency
        [exists(f:stereotype(., 'StartAfter')) or lower-case(normalize-space(@name)) eq 'startafter']"/>
  </xsl:function>

  <!-- $instances (in document order) with their pim:start-after children
       and @start-order (see the header) -->
  <xsl:function name="fp:sequence" as="element(pim:instance)*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="instance-tree" as="document-node()"/>
    <xsl:variable name="root" as="document-node()" select="root($model)"/>
    <xsl:variable name="deps" as="element(pim:dependency)*" select="fp:start-after-dependencies($model)"/>
    <!-- instance xmi-id -> position in document order -->
    <xsl:variable name="position" as="map(xs:string, xs:integer)"
        select="map:merge(for $k in 1 to count($instances) return map { string($instances[$k]/@xmi-id): $k })"/>
    <!-- the constraints: one fp:edge per (supplier, client) pair of a
         dependency, from the position of the earlier instance to the
         position of the later one -->
    <xsl:variable name="graph" as="document-node()">
      <xsl:document>
        <xsl:for-each select="$deps">
          <xsl:variable name="d" as="element(pim:dependency)" select="."/>
          <xsl:variable name="ends" as="element(pim:instance)*">
            <xsl:for-each select="pim:client, pim:supplier">
              <xsl:variable name="i" as="element(pim:instance)?"
                  select="key('fp:instance-by-part', @element, $instance-tree)"/>
              <xsl:if test="empty($i)">
                <xsl:variable name="e" as="element()?" select="key('fp:id', @element, $root)"/>
                <xsl:sequence select="f:fail('BND012', $d/@id, 'StartAfter dependency ''' || $d/@name
                    || ''' has ' || local-name() || ' '
                    || (if (empty($e)) then '''' || @element || ''', which is not in the model'
                        else local-name($e) || ' ''' || $e/@name || ''', which is not a component instance')
                    || ': client and supplier must be parts that become instances'
                    || ' (or components, in a model without a composite component)')"/>
              </xsl:if>
              <xsl:sequence select="$i"/>
            </xsl:for-each>
          </xsl:variable>
          <xsl:variable name="clients" as="element(pim:instance)*" select="$ends[position() le count($d/pim:client)]"/>
          <xsl:for-each select="$ends[position() gt count($d/pim:client)]">
            <xsl:variable name="s" as="element(pim:instance)" select="."/>
            <xsl:for-each select="$clients">
              <fp:edge from="{$position($s/@xmi-id)}" to="{$position(@xmi-id)}" instance="{$s/@name}" dependency="{$d/@id}"/>
            </xsl:for-each>
          </xsl:for-each>
        </xsl:for-each>
      </xsl:document>
    </xsl:variable>
    <xsl:variable name="edges" as="element(fp:edge)*" select="$graph/fp:edge"/>
    <!-- how many constraints each constrained instance waits for -->
    <xsl:variable name="in-degree" as="map(xs:integer, xs:integer)">
      <xsl:map>
        <xsl:for-each-group select="$edges" group-by="xs:integer(@to)">
          <xsl:map-entry key="current-grouping-key()" select="count(current-group())"/>
        </xsl:for-each-group>
      </xsl:map>
    </xsl:variable>
    <xsl:variable name="n" as="xs:integer" select="count($instances)"/>
    <!-- Kahn's algorithm; $free: the positions with no constraint, in
         order; $released: the positions whose constraints all started,
         sorted; each step starts the smallest position of the two -->
    <xsl:variable name="order" as="document-node()">
      <xsl:document>
        <xsl:iterate select="1 to $n">
          <xsl:param name="free" as="xs:integer*"
              select="(1 to $n)[not(map:contains($in-degree, .))]"/>
          <xsl:param name="released" as="xs:integer*" select="()"/>
          <xsl:param name="waiting" as="map(xs:integer, xs:integer)" select="$in-degree"/>
          <xsl:variable name="next" as="xs:integer?" select="min(($free[1], $released[1]))"/>
          <xsl:choose>
            <xsl:when test="empty($next)">
              <xsl:break/>
            </xsl:when>
            <xsl:otherwise>
              <fp:placed position="{$next}" start-order="{.}"/>
              <xsl:variable name="after" as="map(xs:integer, xs:integer)">
                <xsl:map>
                  <xsl:for-each-group select="key('fp:edge-from', string($next), $graph)" group-by="xs:integer(@to)">
                    <xsl:map-entry key="current-grouping-key()"
                        select="$waiting(current-grouping-key()) - count(current-group())"/>
                  </xsl:for-each-group>
                </xsl:map>
              </xsl:variable>
              <xsl:variable name="now-free" as="xs:integer*"
                  select="map:keys($after)[$after(.) eq 0]"/>
              <xsl:next-iteration>
                <xsl:with-param name="free" select="if ($free[1] eq $next) then subsequence($free, 2) else $free"/>
                <xsl:with-param name="released"
                    select="let $rest := (if ($released[1] eq $next) then subsequence($released, 2) else $released)
                            return if (empty($now-free)) then $rest else sort(($rest, $now-free))"/>
                <xsl:with-param name="waiting" as="map(xs:integer, xs:integer)">
                  <xsl:iterate select="map:keys($after)">
                    <xsl:param name="m" as="map(xs:integer, xs:integer)" select="$waiting"/>
                    <xsl:on-completion select="$m"/>
                    <xsl:next-iteration>
                      <xsl:with-param name="m" select="map:put($m, ., $after(.))"/>
                    </xsl:next-iteration>
                  </xsl:iterate>
                </xsl:with-param>
              </xsl:next-iteration>
            </xsl:otherwise>
          </xsl:choose>
        </xsl:iterate>
      </xsl:document>
    </xsl:variable>
    <xsl:for-each select="$instances">
      <xsl:variable name="p" as="xs:integer" select="position()"/>
      <xsl:copy>
        <xsl:sequence select="@*"/>
        <xsl:for-each select="key('fp:placed', string($p), $order)">
          <xsl:attribute name="start-order" select="@start-order"/>
        </xsl:for-each>
        <xsl:sequence select="node()"/>
        <xsl:for-each select="key('fp:edge-to', string($p), $graph)">
          <pim:start-after instance="{@instance}" xmi-id="{@dependency}"/>
        </xsl:for-each>
      </xsl:copy>
    </xsl:for-each>
  </xsl:function>

  <!-- ========================================================== hosts -->
  <xsl:function name="fp:host" as="element(pim:host)">
    <xsl:param name="n" as="element(pim:node)"/>
    <xsl:param name="host-count" as="xs:integer"/>
    <xsl:variable name="hn" as="xs:string?" select="fp:tag($n, 'Host', 'hostname')[normalize-space(.)]"/>
    <xsl:variable name="ad" as="xs:string?" select="fp:tag($n, 'Host', 'address')[normalize-space(.)]"/>
    <xsl:variable name="hostname" as="xs:string" select="($hn, string($n/@name))[1]"/>
    <pim:host xmi-id="{$n/@id}" name="{$n/@name}" hostname="{$hostname}"
              hostname-source="{if (exists($hn)) then 'stereotype' else 'name'}"
              address="{if (exists($ad)) then $ad else if ($host-count eq 1) then 'localhost' else $hostname}"
              address-source="{if (exists($ad)) then 'stereotype' else 'default'}"/>
  </xsl:function>

  <!-- ====================================================== libraries -->
  <xsl:function name="fp:libraries" as="element(pim:library)*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:variable name="all" as="element(pim:artifact)*" select="$model/pim:platform//pim:artifact"/>
    <xsl:variable name="profiled" as="element(pim:artifact)*" select="$all[exists(f:stereotype(., 'Library'))]"/>
    <xsl:for-each select="if (exists($profiled)) then $profiled else $all">
      <xsl:variable name="p" as="xs:string?" select="fp:tag(., 'Library', 'path')[normalize-space(.)]"/>
      <xsl:variable name="t" as="xs:string?" select="fp:tag(., 'Library', 'target')[normalize-space(.)]"/>
      <xsl:variable name="i" as="xs:string?" select="fp:tag(., 'Library', 'includeDir')[normalize-space(.)]"/>
      <xsl:variable name="path" as="xs:string"
          select="translate(($p, @file-name[normalize-space(.)], @name)[1], '\', '/')"/>
      <pim:library xmi-id="{@id}" name="{@name}" path="{$path}"
                   path-source="{if (exists($p)) then 'stereotype' else if (normalize-space(@file-name)) then 'file-name' else 'name'}"
                   absolute="{starts-with($path, '/') or matches($path, '^[A-Za-z]:/')}"
                   target="{($t, @name)[1]}"
                   target-source="{if (exists($t)) then 'stereotype' else 'name'}"
                   include-dir="{($i, 'include')[1]}">
        <xsl:for-each select="pim:manifestation">
          <pim:manifests element="{@element}"/>
        </xsl:for-each>
      </pim:library>
    </xsl:for-each>
  </xsl:function>

  <!-- ====================================================== instances -->
  <xsl:function name="fp:instance" as="element(pim:instance)">
    <xsl:param name="part" as="element(pim:part)?"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:param name="top" as="element(pim:component)?"/>
    <xsl:param name="ees" as="element(pim:node)*"/>
    <xsl:param name="hosts" as="element(pim:node)*"/>
    <xsl:variable name="root" as="document-node()" select="root($c)"/>
    <xsl:variable name="r" as="element(pim:class)?" select="fp:realizing-class($c)"/>
    <xsl:variable name="ids" as="xs:string*" select="($part/@id, $c/@id, $top/@id, $r/@id) ! string(.)"/>
    <xsl:variable name="artifact-ids" as="xs:string*"
        select="key('fp:manifestation-by-element', $ids, $root)/../@id ! string(.)"/>
    <xsl:variable name="deployments" as="element(pim:deployment)*"
        select="key('fp:deployment-by-deployed', ($ids, $artifact-ids), $root)"/>
    <xsl:variable name="ee" as="element(pim:node)?" select="fp:instance-ee($part, $c, $top, $ees)"/>
    <xsl:variable name="inst-id" as="xs:string" select="string(($part/@id, $c/@id)[1])"/>
    <xsl:if test="empty($ee)">
      <xsl:sequence select="f:fail-all(fp:no-ee-problem($part, $c, $ees))"/>
    </xsl:if>
    <xsl:variable name="host" as="element(pim:node)?"
        select="(fp:host-of($ee, $deployments/.., $hosts), if (count($hosts) eq 1) then $hosts else ())[1]"/>
    <pim:instance name="{f:cpp-identifier(($part/@name[normalize-space(.)], $c/@name)[1])}"
                  xmi-id="{$inst-id}" component="{$c/@id}">
      <xsl:if test="$top"><xsl:attribute name="composite" select="$top/@id"/></xsl:if>
      <xsl:if test="$host"><xsl:attribute name="host" select="$host/@id"/></xsl:if>
      <xsl:attribute name="execution-environment" select="$ee/@id"/>
      <xsl:attribute name="middleware" select="fp:middleware($ee)"/>
      <xsl:for-each select="fp:tag($ee, 'Middleware', 'version')[normalize-space(.)]">
        <xsl:attribute name="middleware-version" select="."/>
      </xsl:for-each>
      <xsl:if test="$r"><xsl:attribute name="realization" select="$r/@id"/></xsl:if>
      <!-- only the elements with an Activity stereotype can give a tag -->
      <xsl:sequence select="fp:activity(($part, $c, $r)[exists(f:stereotype(., 'Activity'))], $r, $ee, $inst-id)"/>
      <!-- every deployment that reaches the instance, so the deployment
           rules (schemas/pim/1/pim.sch) can see one deployed twice -->
      <xsl:for-each select="$deployments">
        <xsl:variable name="d-ee" as="element(pim:node)?" select="fp:deployment-ee(.)"/>
        <xsl:variable name="d-host" as="element(pim:node)?" select="fp:host-of($d-ee, .., $hosts)"/>
        <pim:deployed-on deployment="{@id}">
          <xsl:if test="$d-ee"><xsl:attribute name="execution-environment" select="$d-ee/@id"/></xsl:if>
          <xsl:if test="$d-host"><xsl:attribute name="host" select="$d-host/@id"/></xsl:if>
        </pim:deployed-on>
      </xsl:for-each>
    </pim:instance>
  </xsl:function>

  <!-- the execution environment of the instance of $part (or of
       component $c when instances come from components), as fp:instance
       finds it -->
  <xsl:function name="fp:instance-ee" as="element(pim:node)?">
    <xsl:param name="part" as="element(pim:part)?"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:param name="top" as="element(pim:component)?"/>
    <xsl:param name="ees" as="element(pim:node)*"/>
    <xsl:variable name="root" as="document-node()" select="root($c)"/>
    <xsl:variable name="r" as="element(pim:class)?" select="fp:realizing-class($c)"/>
    <xsl:variable name="ids" as="xs:string*" select="($part/@id, $c/@id, $top/@id, $r/@id) ! string(.)"/>
    <xsl:variable name="artifact-ids" as="xs:string*"
        select="key('fp:manifestation-by-element', $ids, $root)/../@id ! string(.)"/>
    <xsl:sequence select="(key('fp:deployment-by-deployed', ($ids, $artifact-ids), $root) ! fp:deployment-ee(.),
                           fp:owner-ee($c),
                           if (count($ees) eq 1) then $ees else ())[1]"/>
  </xsl:function>

  <!-- the execution environment of the node that owns component $c in
       the XMI (EA nests a component in the node it runs on): the node
       itself, else the first one nested in it -->
  <xsl:function name="fp:owner-ee" as="element(pim:node)?">
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:variable name="node" as="element(pim:node)?" select="$c/@node ! key('fp:id', ., root($c))[self::pim:node]"/>
    <xsl:sequence select="($node[@kind eq 'execution-environment'], $node//pim:node[@kind eq 'execution-environment'])[1]"/>
  </xsl:function>

  <!-- BND006 about the instance of $part / $c -->
  <xsl:function name="fp:no-ee-problem" as="map(*)">
    <xsl:param name="part" as="element(pim:part)?"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:param name="ees" as="element(pim:node)*"/>
    <xsl:sequence select="map { 'code': 'BND006', 'id': string(($part/@id, $c/@id)[1]), 'message':
        'component instance ''' || ($part/@name, $c/@name)[1] || ''' is deployed to no execution environment'
        || ' and the model has ' || count($ees) || ' of them' }"/>
  </xsl:function>

  <!-- the execution environment deployment $d reaches: its target, else
       the first one nested in its target -->
  <xsl:function name="fp:deployment-ee" as="element(pim:node)?">
    <xsl:param name="d" as="element(pim:deployment)"/>
    <xsl:sequence select="if ($d/../@kind eq 'execution-environment') then $d/..
                          else ($d/..//pim:node[@kind eq 'execution-environment'])[1]"/>
  </xsl:function>

  <!-- the host of execution environment $ee (the nearest enclosing node
       among $hosts), else the first of the deployment targets $targets that
       is a host -->
  <xsl:function name="fp:host-of" as="element(pim:node)?">
    <xsl:param name="ee" as="element(pim:node)?"/>
    <xsl:param name="targets" as="element()*"/>
    <xsl:param name="hosts" as="element(pim:node)*"/>
    <xsl:sequence select="($ee/ancestor::pim:node[. intersect $hosts][1], $targets[. intersect $hosts])[1]"/>
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
    <xsl:param name="r" as="element(pim:class)?"/>
    <xsl:param name="ee" as="element(pim:node)?"/>
    <xsl:param name="conv" as="xs:string"/>
    <xsl:param name="default" as="xs:string"/>
    <xsl:variable name="t" as="xs:string?" select="fp:first-tag($stereo-on, 'Activity', $tag)"/>
    <xsl:variable name="c" as="xs:string?" select="fp:conv($r, $conv)[normalize-space(.)]"/>
    <xsl:variable name="e" as="xs:string?"
        select="if ($conv eq 'sample') then () else fp:conv($ee, $conv)[normalize-space(.)]"/>
    <xsl:sequence select="if (exists($t)) then ($t, 'stereotype',
                              string(($stereo-on ! f:stereotype(., 'Activity'))[pim:tag[@name eq $tag][normalize-space(@value)]][1]/@id))
                          else if (exists($c)) then ($c, 'realizing-class', fp:conv-holder($r, $conv))
                          else if (exists($e)) then ($e, 'execution-environment', fp:conv-holder($ee, $conv))
                          else ($default, 'default', '')"/>
  </xsl:function>

  <xsl:function name="fp:activity" as="element(pim:activity)">
    <xsl:param name="stereo-on" as="element()*"/>
    <xsl:param name="r" as="element(pim:class)?"/>
    <xsl:param name="ee" as="element(pim:node)?"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:variable name="period" as="xs:string+" select="fp:activity-value($stereo-on, 'period', $r, $ee, 'sample', '0')"/>
    <xsl:variable name="prio" as="xs:string+" select="fp:activity-value($stereo-on, 'priority', $r, $ee, 'priority', '0')"/>
    <xsl:variable name="sched" as="xs:string+" select="fp:activity-value($stereo-on, 'scheduler', $r, $ee, 'scheduler', 'OTHER')"/>
    <xsl:variable name="cpu" as="xs:string+" select="fp:activity-value($stereo-on, 'cpuAffinity', $r, $ee, 'cpuAffinity', '0')"/>
    <xsl:variable name="s" as="xs:string"
        select="replace(replace(upper-case(fp:literal(fp:strip($sched[1]))), '^(ORO_)?SCHED_', ''), '^OTHERS$', 'OTHER')"/>
    <pim:activity period="{fp:number($period[1], 'period', fp:holder($period, $id))}" period-source="{$period[2]}"
                  priority="{fp:integer($prio[1], 'priority', fp:holder($prio, $id))}" priority-source="{$prio[2]}"
                  scheduler="{fp:enum($s, ('RT', 'OTHER'), 'scheduler', fp:holder($sched, $id))}" scheduler-source="{$sched[2]}"
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

  <!-- ============================================ components and ports -->
  <xsl:function name="fp:bound-component" as="element(pim:bound-component)">
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:variable name="r" as="element(pim:class)?" select="fp:realizing-class($c)"/>
    <xsl:variable name="h" as="xs:string?" select="fp:tag($r, 'AtomicCode', 'header')[normalize-space(.)]"/>
    <xsl:variable name="n" as="xs:string?" select="fp:tag($r, 'AtomicCode', 'cppName')[normalize-space(.)]"/>
    <xsl:variable name="cpp" as="xs:string?" select="($n, $r/@name)[1]"/>
    <xsl:if test="$r and not(normalize-space($cpp) and (every $part in tokenize(replace(string($cpp), '^::', ''), '::')
                             satisfies matches($part, '^[A-Za-z_][A-Za-z0-9_]*$')))">
      <xsl:sequence select="f:fail('BND011', string($r/@id), 'the realizing class of component '''
          || $c/@name || ''' has no usable C++ name (''' || string($cpp)
          || '''): name the class, or give its AtomicCode stereotype a cppName')"/>
    </xsl:if>
    <pim:bound-component component="{$c/@id}" name="{$c/@name}">
      <xsl:if test="$r">
        <xsl:attribute name="realization" select="$r/@id"/>
        <xsl:attribute name="realization-name" select="$r/@name"/>
        <xsl:attribute name="header" select="($h, $r/@name || '.hpp')[1]"/>
        <xsl:attribute name="header-source" select="if (exists($h)) then 'stereotype' else 'default'"/>
        <xsl:attribute name="cpp-name" select="($n, $r/@name)[1]"/>
        <xsl:attribute name="cpp-name-source" select="if (exists($n)) then 'stereotype' else 'name'"/>
      </xsl:if>
      <xsl:for-each select="$c/pim:port">
        <xsl:sequence select="fp:data-ports(., $c, $r)"/>
      </xsl:for-each>
    </pim:bound-component>
  </xsl:function>

  <!-- (interface id, direction) pairs of a port, flattened: id, dir, id, dir ... -->
  <xsl:function name="fp:port-interfaces" as="xs:string*">
    <xsl:param name="p" as="element(pim:port)"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:param name="r" as="element(pim:class)?"/>
    <xsl:variable name="root" as="document-node()" select="root($p[1])"/>
    <xsl:variable name="t" as="element()?" select="key('fp:id', $p/@type, $root)"/>
    <xsl:variable name="conj" as="xs:boolean" select="$p/@conjugated = ('true', '1')"/>
    <xsl:sequence select="
        if ($p/pim:provided or $p/pim:required) then
          ($p/pim:provided ! (string(@interface), 'out'), $p/pim:required ! (string(@interface), 'in'))
        else if ($t/self::pim:interface) then
          (string($t/@id),
           if (($c, $r)/pim:requires/@interface = $t/@id) then 'in'
           else if (($c, $r)/pim:provides/@interface = $t/@id) then 'out'
           else if ($conj) then 'in' else 'out')
        else if ($t/self::pim:class) then
          ($t/pim:provides ! (string(@interface), if ($conj) then 'in' else 'out'),
           $t/pim:requires ! (string(@interface), if ($conj) then 'out' else 'in'))
        else if (fp:is-data-type($t)) then (string($t/@id), if ($conj) then 'in' else 'out')
        else if (empty($t) and $p/@primitive) then (string($p/@id), if ($conj) then 'in' else 'out')
        else ()"/>
  </xsl:function>

  <!-- true when port $p is typed by an interface that neither the
       component nor its realizing class provides or requires, and has no
       provided / required lists: fp:port-interfaces then guesses its
       direction from conjugation alone (rule APP006 says so) -->
  <xsl:function name="fp:direction-guessed" as="xs:boolean">
    <xsl:param name="p" as="element(pim:port)"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:param name="r" as="element(pim:class)?"/>
    <xsl:variable name="t" as="element()?" select="key('fp:id', $p/@type, root($p))"/>
    <xsl:sequence select="not($p/pim:provided or $p/pim:required) and exists($t/self::pim:interface)
                          and not(($c, $r)/(pim:requires | pim:provides)/@interface = $t/@id)"/>
  </xsl:function>

  <!-- the problems of the data ports of port $p (BND002, BND004,
       BND005), as maps for f:fail-all -->
  <xsl:function name="fp:port-problems" as="map(*)*">
    <xsl:param name="p" as="element(pim:port)"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:param name="r" as="element(pim:class)?"/>
    <xsl:variable name="root" as="document-node()" select="root($p[1])"/>
    <xsl:variable name="pairs" as="xs:string*" select="fp:port-interfaces($p, $c, $r)"/>
    <xsl:for-each select="1 to count($pairs) idiv 2">
      <xsl:variable name="i" as="element()?" select="key('fp:id', $pairs[2 * current() - 1], $root)"/>
      <xsl:variable name="data" as="element(pim:attribute)*" select="$i/pim:attribute"/>
      <xsl:choose>
        <xsl:when test="fp:is-data-type($i)"/>
        <xsl:when test="not($i/self::pim:interface)">
          <xsl:sequence select="map { 'code': 'BND002', 'id': string($p/@id), 'message': 'port ''' || $p/@name
              || ''' refers to ''' || $pairs[2 * current() - 1] || ''', which is not an interface' }"/>
        </xsl:when>
        <xsl:when test="empty($data)">
          <xsl:sequence select="map { 'code': 'BND004', 'id': string($i/@id), 'message': 'interface ''' || $i/@name
              || ''' (port ''' || $p/@name || ''') carries no datum: give it one attribute' }"/>
        </xsl:when>
        <xsl:when test="count($data) gt 1">
          <xsl:sequence select="map { 'code': 'BND005', 'id': string($i/@id), 'message': 'interface ''' || $i/@name
              || ''' (port ''' || $p/@name || ''') carries ' || count($data)
              || ' attributes (' || string-join($data/@name, ', ') || '): an interface carries exactly one datum' }"/>
        </xsl:when>
      </xsl:choose>
    </xsl:for-each>
  </xsl:function>

  <!-- a port's own type that is its data (a data type, primitive or
       enumeration of the model; the port itself for a library primitive) -->
  <xsl:function name="fp:is-data-type" as="xs:boolean">
    <xsl:param name="t" as="element()?"/>
    <xsl:sequence select="exists($t/(self::pim:datatype | self::pim:primitive | self::pim:enumeration
                                     | self::pim:port[@primitive]))"/>
  </xsl:function>

  <xsl:function name="fp:data-ports" as="element(pim:data-port)*">
    <xsl:param name="p" as="element(pim:port)"/>
    <xsl:param name="c" as="element(pim:component)"/>
    <xsl:param name="r" as="element(pim:class)?"/>
    <xsl:variable name="root" as="document-node()" select="root($p[1])"/>
    <xsl:sequence select="f:fail-all(fp:port-problems($p, $c, $r))"/>
    <xsl:variable name="pairs" as="xs:string*" select="fp:port-interfaces($p, $c, $r)"/>
    <xsl:variable name="n" as="xs:integer" select="count($pairs) idiv 2"/>
    <xsl:for-each select="1 to $n">
      <xsl:variable name="i" as="element()?" select="key('fp:id', $pairs[2 * current() - 1], $root)"/>
      <xsl:choose>
        <xsl:when test="fp:is-data-type($i)">
          <!-- a port typed by a data type carries that data itself: the
               type stands for the interface, the port for the datum -->
          <pim:data-port port="{$p/@id}" name="{f:cpp-identifier($p/@name)}"
                         port-name="{$p/@name}" direction="{$pairs[2 * current()]}"
                         interface="{$i/@id}" interface-name="{($i/self::pim:port/@type-name, $i/@name)[1]}"
                         datum="{$p/@id}" datum-name="{$p/@name}">
            <xsl:sequence select="$p/(@primitive, @type, @type-name, @upper)"/>
          </pim:data-port>
        </xsl:when>
        <xsl:otherwise>
          <xsl:variable name="data" as="element(pim:attribute)*" select="$i/pim:attribute"/>
          <pim:data-port port="{$p/@id}"
                         name="{f:cpp-identifier(if ($n eq 1) then $p/@name else $p/@name || '_' || $i/@name)}"
                         port-name="{$p/@name}" direction="{$pairs[2 * current()]}"
                         interface="{$i/@id}" interface-name="{$i/@name}"
                         datum="{$data/@id}" datum-name="{$data/@name}">
            <xsl:if test="fp:direction-guessed($p, $c, $r)">
              <xsl:attribute name="direction-source" select="'guessed'"/>
            </xsl:if>
            <xsl:sequence select="$data/(@primitive, @type, @type-name, @upper)"/>
          </pim:data-port>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:for-each>
  </xsl:function>

  <!-- ==================================================== connections -->
  <!-- the policy of a connection that no ConnectionPolicy stereotype
       configures; its attributes are also the value of each tag a
       stereotype leaves out -->
  <xsl:variable name="fp:default-policy" as="element(pim:policy)">
    <pim:policy type="DATA" size="1" lock-policy="LOCK_FREE" init="false" pull="false" topic="" source="default"/>
  </xsl:variable>

  <xsl:function name="fp:policy" as="element(pim:policy)">
    <xsl:param name="candidates" as="element()*"/>
    <xsl:variable name="e" as="element()?" select="$candidates[exists(f:stereotype(., 'ConnectionPolicy'))][1]"/>
    <xsl:sequence select="if (empty($e)) then $fp:default-policy else fp:policy-of($e)"/>
  </xsl:function>

  <!-- the policy given by the ConnectionPolicy stereotype of $e -->
  <xsl:function name="fp:policy-of" as="element(pim:policy)">
    <xsl:param name="e" as="element()"/>
    <!-- the stereotype application holds the values: errors point at it -->
    <xsl:variable name="id" as="xs:string?" select="(f:stereotype($e, 'ConnectionPolicy')/@id, $e/@id)[1]"/>
    <xsl:variable name="default" as="element(pim:policy)" select="$fp:default-policy"/>
    <xsl:variable name="type" as="xs:string"
        select="fp:enum((fp:tag($e, 'ConnectionPolicy', 'type')[normalize-space(.)], $default/@type)[1],
                        ('DATA', 'BUFFER', 'CIRCULAR_BUFFER'), 'connection type', $id)"/>
    <pim:policy type="{$type}"
        size="{let $s := fp:tag($e, 'ConnectionPolicy', 'size')[normalize-space(.)]
               return if (exists($s)) then fp:integer($s, 'size', $id) else $default/@size}"
        lock-policy="{fp:enum((fp:tag($e, 'ConnectionPolicy', 'lockPolicy')[normalize-space(.)], $default/@lock-policy)[1],
                             ('UNSYNC', 'LOCKED', 'LOCK_FREE'), 'lock policy', $id)}"
        init="{fp:boolean((fp:tag($e, 'ConnectionPolicy', 'init')[normalize-space(.)], $default/@init)[1], 'init', $id)}"
        pull="{fp:boolean((fp:tag($e, 'ConnectionPolicy', 'pull')[normalize-space(.)], $default/@pull)[1], 'pull', $id)}"
        topic="{fp:tag($e, 'ConnectionPolicy', 'topic')}"
        source="{if ($e/self::pim:connector) then 'connector'
                 else if ($e/self::pim:port) then 'port' else 'interface'}"
        source-element="{$e/@id}" holder="{$id}"/>
  </xsl:function>

  <xsl:function name="fp:connection-name" as="xs:string">
    <xsl:param name="connector" as="element(pim:connector)?"/>
    <xsl:param name="interface" as="element(pim:interface)"/>
    <xsl:sequence select="if (normalize-space($connector/@name)) then f:cpp-identifier($connector/@name)
                          else f:cpp-identifier($interface/@name || 'Conn')"/>
  </xsl:function>

  <!-- ball-and-socket: one connection point per interface -->
  <xsl:function name="fp:connections-from-interfaces" as="element(pim:connection)*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:param name="work" as="document-node()"/>
    <xsl:variable name="root" as="document-node()" select="root($model[1])"/>
    <xsl:for-each select="$model/pim:application//pim:interface">
      <xsl:variable name="ips" as="element(fp:ip)*" select="key('fp:ip-by-interface', @id, $work)"/>
      <xsl:variable name="w" as="element(fp:ip)*" select="$ips[@direction eq 'out']"/>
      <xsl:variable name="r" as="element(fp:ip)*" select="$ips[@direction eq 'in']"/>
      <xsl:if test="exists($w) and exists($r)">
        <pim:connection name="{fp:connection-name((), .)}" xmi-id="{@id}" interface="{@id}">
          <xsl:sequence select="fp:policy((key('fp:id', ($w, $r)/@port, $root), .))"/>
          <xsl:for-each select="$w"><pim:writer instance="{@instance}" port="{@port}" data-port="{@data-port}"/></xsl:for-each>
          <xsl:for-each select="$r"><pim:reader instance="{@instance}" port="{@port}" data-port="{@data-port}"/></xsl:for-each>
        </pim:connection>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>

  <!-- connector mode: writer->reader pairs grouped by writer port -->
  <xsl:function name="fp:connections-from-connectors" as="element(pim:connection)*">
    <xsl:param name="connectors" as="element(pim:connector)*"/>
    <xsl:param name="work" as="document-node()"/>
    <xsl:variable name="root" as="document-node()" select="root($connectors[1])"/>
    <xsl:variable name="pairs" as="element(fp:pair)*">
      <xsl:for-each select="$connectors">
        <xsl:variable name="k" as="element(pim:connector)" select="."/>
        <xsl:variable name="ips" as="element(fp:ip)*"
            select="pim:end[@part] ! key('fp:ip-by-end', @part || '|' || @role, $work)"/>
        <xsl:variable name="found" as="element(fp:pair)*">
          <xsl:for-each select="$ips[@direction eq 'out']">
            <xsl:variable name="wr" as="element(fp:ip)" select="."/>
            <xsl:for-each select="$ips[@direction eq 'in'][@part ne $wr/@part or @port ne $wr/@port]
                                      [@interface eq $wr/@interface or @type-key eq $wr/@type-key]">
              <fp:pair connector="{$k/@id}" interface="{$wr/@interface}"
                       w-instance="{$wr/@instance}" w-port="{$wr/@port}" w-dp="{$wr/@data-port}"
                       r-instance="{@instance}" r-port="{@port}" r-dp="{@data-port}"/>
            </xsl:for-each>
          </xsl:for-each>
        </xsl:variable>
        <xsl:sequence select="$found"/>
      </xsl:for-each>
    </xsl:variable>
    <!-- every connector that joins nothing and every input fed twice, at once -->
    <xsl:variable name="problems" as="map(*)*">
      <xsl:for-each select="$connectors[not(@id = $pairs/@connector)]">
        <xsl:sequence select="map { 'code': 'BND007', 'id': string(@id), 'message': 'connector ''' || @name
            || ''' joins no output port to an input port of the same data type' }"/>
      </xsl:for-each>
      <xsl:for-each-group select="$pairs" group-by="@r-instance || '.' || @r-dp">
        <xsl:if test="count(distinct-values(current-group()/(@w-instance || '.' || @w-dp))) gt 1">
          <xsl:sequence select="map { 'code': 'BND008', 'id': string(current-group()[1]/@r-port),
              'message': 'input port ' || current-grouping-key() || ' is fed by several output ports ('
              || string-join(distinct-values(current-group()/(@w-instance || '.' || @w-dp)), ', ') || ')' }"/>
        </xsl:if>
      </xsl:for-each-group>
    </xsl:variable>
    <xsl:sequence select="f:fail-all($problems)"/>
    <xsl:for-each-group select="$pairs" group-by="@w-instance || '.' || @w-dp">
      <xsl:variable name="g" as="element(fp:pair)+" select="current-group()"/>
      <xsl:variable name="ks" as="element(pim:connector)*"
          select="key('fp:id', distinct-values($g/@connector), $root)"/>
      <xsl:variable name="iface" as="element(pim:interface)" select="key('fp:id', $g[1]/@interface, $root)"/>
      <pim:connection name="{fp:connection-name($ks[1], $iface)}" xmi-id="{$ks[1]/@id}"
                      interface="{$iface/@id}" connectors="{$ks/@id}">
        <xsl:sequence select="fp:policy(($ks, key('fp:id', ($g[1]/@w-port, $g/@r-port), $root), $iface))"/>
        <pim:writer instance="{$g[1]/@w-instance}" port="{$g[1]/@w-port}" data-port="{$g[1]/@w-dp}"/>
        <xsl:for-each-group select="$g" group-by="@r-instance || '.' || @r-dp">
          <pim:reader instance="{@r-instance}" port="{@r-port}" data-port="{@r-dp}"/>
        </xsl:for-each-group>
      </pim:connection>
    </xsl:for-each-group>
  </xsl:function>
</xsl:stylesheet>
